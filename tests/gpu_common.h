// Helpers every GPU suite shares: the render target size, a log callback counting the header's
// "RBL:" lines, the front camera, a solid texture and a one-call scene. Included by test_render.c
// (test_gpu) and test_api_main.c (the sanitized API suite).
#ifndef RBL_TEST_GPU_COMMON_H
#define RBL_TEST_GPU_COMMON_H

#define TARGET 64

static int warnings = 0;
static char lastWarning[512];
// Counts the header's log lines that pass the current trace level (warnings unless a test lowers it)
static inline void countingLog(int level, const char *text, va_list args)
{
    (void)level;
    char line[512];
    vsnprintf(line, sizeof(line), text, args);
    if (strncmp(line, "RBL:", 4) == 0) { warnings++; memcpy(lastWarning, line, sizeof(line)); }
}

static inline Camera3D frontCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 0.0f, 5.0f };
    c.target = (Vector3){ 0.0f, 0.0f, 0.0f };
    c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = 45.0f;
    c.projection = CAMERA_PERSPECTIVE;
    return c;
}

static inline Texture2D solidTexture(Color c)
{
    Image img = GenImageColor(4, 4, c);
    Texture2D t = LoadTextureFromImage(img);
    UnloadImage(img);
    return t;
}

// The frame's scene for every lit program: count lights and a flat ambient, everything else default
// (no fog, exposure 1, no shadows). Returns RblSetScene's verdict.
static inline bool renderSetLights(const RblLight *lights, int count, Color ambient)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights;
    scene.lightCount = count;
    scene.ambient = ambient;
    return RblSetScene(&scene);
}

#endif
