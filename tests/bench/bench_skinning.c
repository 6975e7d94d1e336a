// Benchmark suite "skinning": a GPU-skinned Model (RblLitShaderDesc.skinning) against raylib's CPU
// skinning of the same Model (GPU headless GL).
//   Model: tests/skin_rig.h's column, 2048 segments per side (16 396 vertices, 3 bones, no plate),
//   Blinn-Phong, one directional light, 512x512 target, the column filling about a tenth of it.
//   gpu frame: UpdateModelAnimation (bone matrices only: the mesh has no animVertices) + RblDrawModel
//              with the skinned program (the vertex stage skins).
//   cpu frame: UpdateModelAnimation of a copy whose mesh has animVertices/animNormals (raylib skins
//              every vertex on the CPU and re-uploads the positions) + UpdateMeshBuffer of the normals
//              (raylib 6.0 sends them to the colour buffer's slot) + RblDrawModel, unskinned program.
//   Each frame: glFinish, clock from UpdateModelAnimation to the return of a glFinish after the
//   draw; the animation time advances every frame (frame = k*0.37 mod 2). One round times one frame
//   of each, order alternating; ratio = median of per-round cpu/gpu.
//   Accuracy: both rendered at keyframe fraction 0.5 (raylib interpolates the same bone matrices for
//   both), per-channel max |gpu - cpu| in 1/255 over every pixel, and over pixels away from edges.
// Rows: skinning,<gpu|cpu>_16396v,ms_per_frame; skinning,cpu_over_gpu,ratio;
//       skinning,gpu_vs_cpu_pixels,<max_all|max_interior>,1/255
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "raymath.h"
#include "harness.h"
#include "bench.h"
#include "skin_rig.h"

#include <math.h>
#include <stdlib.h>

#define SIZE 512
#define SEGMENTS 2048

typedef struct Bench {
    SkinRig gpu, cpu;
    RenderTexture2D target;
    Camera3D camera;
    int frame;
} Bench;

static void DrawOne(Bench *b, SkinRig *rig, float t)
{
    UpdateModelAnimation(rig->model, rig->anim, t);
    // raylib 6.0 re-uploads the CPU-skinned normals into vboId[SHADER_LOC_VERTEX_NORMAL] (3, the colour
    // slot) instead of vboId[2]: upload them where the normals are
    Mesh *m = &rig->model.meshes[0];
    if (m->animNormals != NULL) UpdateMeshBuffer(*m, RL_DEFAULT_SHADER_ATTRIB_LOCATION_NORMAL, m->animNormals, m->vertexCount*3*(int)sizeof(float), 0);
    BeginTextureMode(b->target);
    ClearBackground(BLANK);
    BeginMode3D(b->camera);
    RblDrawModel(rig->model, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
    EndMode3D();
    EndTextureMode();
}

static double TimeOne(Bench *b, SkinRig *rig)
{
    float t = fmodf((float)b->frame*0.37f, 2.0f);
    b->frame++;
    rtFinish();
    double t0 = BenchNowNs();
    DrawOne(b, rig, t);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static void Round(void *ctx, double *out)
{
    Bench *b = (Bench *)ctx;
    static int order = 0;
    order ^= 1;
    if (order) { out[0] = TimeOne(b, &b->gpu); out[1] = TimeOne(b, &b->cpu); }
    else { out[1] = TimeOne(b, &b->cpu); out[0] = TimeOne(b, &b->gpu); }
    out[2] = out[1]/out[0];
}

int main(void)
{
    const char *backend = rtInitContext(SIZE, SIZE);
    if (backend == NULL) { printf("bench_skinning: no headless GL context, skipped\n"); return 0; }
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.shading.brdf = RBL_BRDF_BLINN_PHONG;
    Shader plain = RblLoadLitShader(desc);
    desc.skinning = true;
    Shader skinned = RblLoadLitShader(desc);
    if (!RblIsLitShaderValid(plain) || !RblIsLitShaderValid(skinned))
    {
        printf("bench_skinning: skinned lit program unavailable (raylib without SUPPORT_GPU_SKINNING?), skipped\n");
        rtCloseContext();
        return 0;
    }
    Bench b;
    memset(&b, 0, sizeof(b));
    b.gpu = skinRigLoadEx(SEGMENTS, false, false);
    b.cpu = skinRigLoadEx(SEGMENTS, false, true);
    b.gpu.model.materials[0].shader = skinned;
    b.cpu.model.materials[0].shader = plain;
    b.target = LoadRenderTexture(SIZE, SIZE);
    b.camera.position = (Vector3){ 3.5f, -5.5f, 2.2f };
    b.camera.target = (Vector3){ 0.3f, 0.0f, 1.2f };
    b.camera.up = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.camera.fovy = 40.0f;
    b.camera.projection = CAMERA_PERSPECTIVE;
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ -0.4f, 1.0f, -0.6f }; sun.color = WHITE; sun.intensity = 1.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 30, 30, 30, 255 };
    RblSetScene(&scene);

    // Accuracy at the midpoint of the bend
    Image img[2];
    SkinRig *rigs[2] = { &b.gpu, &b.cpu };
    for (int k = 0; k < 2; k++) { DrawOne(&b, rigs[k], 0.5f); img[k] = rtReadTarget(b.target); }
    int maxAll = 0, maxInterior = 0, covered = 0;
    for (int y = 0; y < SIZE; y++)
        for (int x = 0; x < SIZE; x++)
        {
            Color p = rtPixel(img[0], x, y), q = rtPixel(img[1], x, y);
            if ((p.a == 0) && (q.a == 0)) continue;
            covered++;
            int d = abs(p.r - q.r);
            if (abs(p.g - q.g) > d) d = abs(p.g - q.g);
            if (abs(p.b - q.b) > d) d = abs(p.b - q.b);
            if (p.a != q.a) d = 255;
            if (d > maxAll) maxAll = d;
            if (!skEdge(img[0], x, y) && !skEdge(img[1], x, y) && (d > maxInterior)) maxInterior = d;
        }
    UnloadImage(img[0]); UnloadImage(img[1]);

    double med[3];
    BenchTiming timing = { 5, 15, 60, 8e9 };
    int runs = BenchMedianOfRuns(Round, &b, 3, timing, med);
    int vertices = b.gpu.model.meshes[0].vertexCount;
    char name[64];
    snprintf(name, sizeof(name), "gpu_%dv", vertices); BenchCsvRow("skinning", name, "ms_per_frame", med[0], "ms");
    snprintf(name, sizeof(name), "cpu_%dv", vertices); BenchCsvRow("skinning", name, "ms_per_frame", med[1], "ms");
    BenchCsvRow("skinning", "cpu_over_gpu", "ratio", med[2], "x");
    BenchCsvRow("skinning", "gpu_vs_cpu_pixels", "max_all", (double)maxAll, "1/255");
    BenchCsvRow("skinning", "gpu_vs_cpu_pixels", "max_interior", (double)maxInterior, "1/255");
    printf("skinning: %d vertices, 3 bones, %dx%d, %s context, median of %d rounds\n", vertices, SIZE, SIZE, backend, runs);
    printf("  GPU skinning (bone matrices + skinned vertex stage)      %8.3f ms/frame\n", med[0]);
    printf("  CPU skinning (raylib UpdateModelAnimation + re-upload)   %8.3f ms/frame  (%.2fx the GPU frame)\n", med[1], med[2]);
    printf("  GPU vs CPU pixels at frame 0.5: max %d/255 over %d covered pixels, %d/255 away from edges\n", maxAll, covered, maxInterior);

    b.gpu.model.materials[0].shader = (Shader){ 0 };
    b.cpu.model.materials[0].shader = (Shader){ 0 };
    skinRigUnload(&b.gpu);
    skinRigUnload(&b.cpu);
    UnloadRenderTexture(b.target);
    RblUnloadLitShader(&plain);
    RblUnloadLitShader(&skinned);
    RblClose();
    rtCloseContext();
    return 0;
}
