// Helpers every GPU suite shares: the render target size, a log callback counting the header's
// "RBL:" lines, the front camera, a solid texture, a one-call scene and a one-billboard lit render.
// Included by gpu_tests.h (test_gpu, test_web) and test_api_main.c (the sanitized API suite).
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

// Normal-map texel for a unit tangent-space normal (OpenGL convention), rounded like an 8-bit map
static inline Color normalTexel(float x, float y, float z)
{
    Color c = { (unsigned char)lroundf((x*0.5f + 0.5f)*255.0f), (unsigned char)lroundf((y*0.5f + 0.5f)*255.0f),
                (unsigned char)lroundf((z*0.5f + 0.5f)*255.0f), 255 };
    return c;
}

// A lit material with a solid albedo and (optionally) a solid normal map, for one-billboard renders
typedef struct { Material material; Texture2D albedo, normal; Shader lit; } Scene;

static inline Scene sceneLoad(Color albedo, Color normal, bool normalMap)
{
    Scene s;
    memset(&s, 0, sizeof(s));
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 2;
    desc.material.normalEncoding = normalMap? RBL_NORMAL_RGB : RBL_NORMAL_NONE;
    s.lit = RblLoadLitShader(desc);
    s.albedo = solidTexture(albedo);
    s.normal = solidTexture(normal);
    s.material = LoadMaterialDefault();
    s.material.shader = s.lit;
    s.material.maps[MATERIAL_MAP_ALBEDO].texture = s.albedo;
    if (normalMap) s.material.maps[MATERIAL_MAP_NORMAL].texture = s.normal;
    return s;
}

static inline void sceneUnload(Scene s)
{
    RblUnloadLitShader(&s.lit);
    UnloadTexture(s.albedo);
    UnloadTexture(s.normal);
    MemFree(s.material.maps);       // not UnloadMaterial: the shader and textures are unloaded above
}

// Draws one billboard (immediate path) into a fresh target and returns the image
static inline Image renderOne(Scene *s, Camera3D cam, RblBillboard b)
{
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(cam);
    RblDrawBillboard(cam, s->material, b);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    return img;
}

static inline int luminance(Color c) { return c.r + c.g + c.b; }

static inline RblBillboard centredQuad(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 2.0f, 2.0f };
    b.origin = (Vector2){ 1.0f, 1.0f };
    return b;
}

static inline RblLight rtPointLight(Vector3 p, float intensity)
{
    RblLight l;
    memset(&l, 0, sizeof(l));
    l.position = p; l.color = WHITE; l.intensity = intensity; l.range = 0.0f;
    return l;
}


#endif
