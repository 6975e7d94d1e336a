// Benchmark suite "materials": material packing on the CPU (no GL).
//   encoding error  angular error (mean, 99th percentile, max; degrees) of encode + decode for
//                   rgb8 (RBL_NORMAL_RGB), xy8 (RBL_NORMAL_XY, z rebuilt), hemioct8 (RBL_NORMAL_HEMIOCT, the
//                   precise encoder) and hemioct8_rounded (plain rounding of the same mapping, decoded by
//                   RblDecodeNormal) over three normal sets:
//                     hemisphere     1,000,000 uniform unit normals of the z >= 0 hemisphere (fixed seed)
//                     bumpy_atlas    every texel of a 1024x1024 procedural height atlas (16x16 frames of
//                                    bumps, ridges and waves), normals from the same central differences as
//                                    RblGenNormalMapFromHeight but unquantised (its RGB8 output would
//                                    measure the RGB8 encoding against itself)
//                     random_atlas   every texel of a 1024x1024 atlas of independent random normals,
//                                    cosine-weighted (dense near +Z, like authored normal maps)
//   bytes per texel of the packed layouts (measured from RblPackMaterial's Images, level 0 and with the
//                   mip chain) against one RGBA8 texture per source map and the four-RGBA8 baseline
//   pack time       RblPackMaterial of a 1024x1024 atlas with every map (albedo RGBA8, RGB8 normal map,
//                   grey specular, occlusion and emissive), without/with mipmaps, without/with frames
//                   (16x16 frames of 60x60 with 2-texel gutters), per encoding; median of timed runs,
//                   reported per megapixel of level 0. Plus the generators per megapixel.
// Rows (suite "materials"):
//   <set>_<encoding>: mean_deg, p99_deg, max_deg, count
//   layout_<maps>: packed_bytes_per_texel, packed_bytes_per_texel_mips, separate_rgba8_bytes_per_texel
//   four_rgba8: bytes_per_texel (albedo, normal, specular/occlusion, emissive as four RGBA8 textures)
//   pack_<encoding>_<mips|nomips>_<frames|noframes>: ms_per_mpixel, runs
//   gen_<function>: ms_per_mpixel
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "harness.h"
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define SUITE               "materials"
#define HEMISPHERE_COUNT    1000000
#define ATLAS_SIZE          1024
#define FRAME_CELLS         16                      // frames per side
#define FRAME_PITCH         (ATLAS_SIZE/FRAME_CELLS)
#define FRAME_GUTTER        2                       // texels of gutter on each side of a frame
#define HEIGHT_STRENGTH     24.0f                   // texel units per height unit of the bumpy atlas (heights ~0..1.5)
#define PI_D                3.14159265358979323846

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
typedef struct NormalSet { const char *name; Vector3 *normals; int count; } NormalSet;

typedef struct PackCase {
    const RblMaterialSource *source;
    RblPackedMaterial packed;
} PackCase;

//----------------------------------------------------------------------------------
// Normal sets
//----------------------------------------------------------------------------------
static unsigned long long rngState = 0x9E3779B97F4A7C15ull;
static double Random01(void)        // xorshift64*, 53 bits
{
    rngState ^= rngState >> 12; rngState ^= rngState << 25; rngState ^= rngState >> 27;
    return (double)((rngState*0x2545F4914F6CDD1Dull) >> 11)/9007199254740992.0;
}

static Vector3 *HemisphereNormals(int count)
{
    Vector3 *n = (Vector3 *)malloc((size_t)count*sizeof(Vector3));
    for (int i = 0; i < count; i++)
    {
        double z = Random01(), phi = 2.0*PI_D*Random01(), r = sqrt(1.0 - z*z);
        n[i] = (Vector3){ (float)(r*cos(phi)), (float)(r*sin(phi)), (float)z };
    }
    return n;
}

static Vector3 *CosineNormals(int count)
{
    Vector3 *n = (Vector3 *)malloc((size_t)count*sizeof(Vector3));
    for (int i = 0; i < count; i++)
    {
        double r = sqrt(Random01()), phi = 2.0*PI_D*Random01();
        n[i] = (Vector3){ (float)(r*cos(phi)), (float)(r*sin(phi)), (float)sqrt(1.0 - r*r) };
    }
    return n;
}

// Procedural height atlas: each frame holds a few spherical bumps, a ridge and a wave (0..1 heights)
static float *BumpyHeights(void)
{
    float *h = (float *)calloc((size_t)ATLAS_SIZE*ATLAS_SIZE, sizeof(float));
    for (int fy = 0; fy < FRAME_CELLS; fy++)
        for (int fx = 0; fx < FRAME_CELLS; fx++)
        {
            double bx[4], by[4], br[4];
            for (int b = 0; b < 4; b++) { bx[b] = 8 + Random01()*48; by[b] = 8 + Random01()*48; br[b] = 4 + Random01()*14; }
            double waveK = 0.1 + Random01()*0.5, ridgeA = Random01()*PI_D;
            for (int y = 0; y < FRAME_PITCH; y++)
                for (int x = 0; x < FRAME_PITCH; x++)
                {
                    // in texel units: a wave, flattened hemispherical bumps and a ridge
                    double v = 1.5*sin(waveK*x)*cos(waveK*0.7*y) + 2.0;
                    for (int b = 0; b < 4; b++)
                    {
                        double dx = x - bx[b], dy = y - by[b], r2 = br[b]*br[b] - dx*dx - dy*dy;
                        if (r2 > 0.0) v += 0.8*sqrt(r2);
                    }
                    double d = fabs((x - 32)*cos(ridgeA) + (y - 32)*sin(ridgeA));
                    if (d < 3.0) v += 3.0 - d;
                    h[(size_t)(fy*FRAME_PITCH + y)*ATLAS_SIZE + fx*FRAME_PITCH + x] = (float)(v/HEIGHT_STRENGTH);
                }
        }
    return h;
}

//----------------------------------------------------------------------------------
// Error measurement (hemioct8_rounded is measured here the same way RblMeasureNormalEncoding does)
//----------------------------------------------------------------------------------
static int CompareDouble(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y)? -1 : (x > y)? 1 : 0;
}

static double AngleDeg(Vector3 a, Vector3 b)
{
    double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    double cx = ay*bz - az*by, cy = az*bx - ax*bz, cz = ax*by - ay*bx;
    return atan2(sqrt(cx*cx + cy*cy + cz*cz), ax*bx + ay*by + az*bz)*(180.0/PI_D);
}

static RblNormalErrorStats MeasureHemiOctRounded(const Vector3 *n, int count)
{
    RblNormalErrorStats s;
    memset(&s, 0, sizeof(s));
    double *e = (double *)malloc((size_t)count*sizeof(double)), sum = 0.0;
    for (int i = 0; i < count; i++)
    {
        double l = sqrt((double)n[i].x*n[i].x + (double)n[i].y*n[i].y + (double)n[i].z*n[i].z);
        double x = n[i].x/l, y = n[i].y/l, z = (n[i].z > 0.0f)? n[i].z/l : 0.0;
        double s1 = fabs(x) + fabs(y) + z, px = x/s1, py = y/s1;
        unsigned char c[3] = { (unsigned char)floor(((px + py)*0.5 + 0.5)*255.0 + 0.5), (unsigned char)floor(((px - py)*0.5 + 0.5)*255.0 + 0.5), 0 };
        e[i] = AngleDeg(n[i], RblDecodeNormal(c, RBL_NORMAL_HEMIOCT));
        sum += e[i];
    }
    qsort(e, (size_t)count, sizeof(double), CompareDouble);
    s.count = count;
    s.mean = sum/count;
    s.p99 = e[(int)ceil(0.99*count) - 1];
    s.max = e[count - 1];
    free(e);
    return s;
}

//----------------------------------------------------------------------------------
// Pack timing
//----------------------------------------------------------------------------------
static void PackRun(void *ctx, double *out)
{
    PackCase *c = (PackCase *)ctx;
    double t0 = BenchNowNs();
    bool ok = RblPackMaterial(c->source, &c->packed);
    out[0] = BenchNowNs() - t0;
    if (!ok) { printf("bench_materials: RblPackMaterial failed\n"); exit(1); }
    RblUnloadPackedMaterial(&c->packed);
}

typedef struct GenCase { int which; Image height; Image albedo; } GenCase;

static void GenRun(void *ctx, double *out)
{
    GenCase *g = (GenCase *)ctx;
    double t0 = BenchNowNs();
    Image img = (g->which == 0)? RblGenNormalMapFromHeight(g->height, 4.0f, true) :
                (g->which == 1)? RblGenHeightFromLuminance(g->albedo) : RblGenOcclusionFromHeight(g->height, 4, 2.0f);
    out[0] = BenchNowNs() - t0;
    UnloadImage(img);
}

static double ImageBytes(Image img)
{
    if (img.data == NULL) return 0.0;
    double bytes = 0.0;
    for (int l = 0, w = img.width, h = img.height; l < img.mipmaps; l++)
    {
        bytes += GetPixelDataSize(w, h, img.format);
        w = (w > 1)? w/2 : 1;
        h = (h > 1)? h/2 : 1;
    }
    return bytes;
}

// ---- GPU: decode cost of each normal encoding, full screen at 1280x720 -----------------------------
#define DECODE_W 1280
#define DECODE_H 720
typedef struct { RenderTexture2D target; Camera3D camera; Material material; RblBillboard quad; } DecodeFrame;

static void DecodeRun(void *ctx, double *out)
{
    DecodeFrame *f = (DecodeFrame *)ctx;
    rtFinish();
    double t0 = BenchNowNs();
    BeginTextureMode(f->target);
    ClearBackground(BLACK);
    BeginMode3D(f->camera);
    RblDrawBillboard(f->camera, f->material, f->quad);
    EndMode3D();
    EndTextureMode();
    rtFinish();                     // the GPU work is what is measured here
    out[0] = BenchNowNs() - t0;
}

// ms per frame for a quad covering every pixel, per layout; the decode cost is the difference to the
// albedo-only variant (same frame, same light). Returns false (no rows) without a GL context.
static bool DecodeCostRows(Image albedo, Image normalMap, double ms[4])
{
    if (rtInitContext(DECODE_W, DECODE_H) == NULL) return false;
    const int encodings[4] = { RBL_NORMAL_NONE, RBL_NORMAL_RGB, RBL_NORMAL_XY, RBL_NORMAL_HEMIOCT };
    const char *names[4] = { "decode_albedo_only", "decode_rgb8", "decode_xy8", "decode_hemioct8" };
    DecodeFrame f;
    memset(&f, 0, sizeof(f));
    f.target = LoadRenderTexture(DECODE_W, DECODE_H);
    f.camera.position = (Vector3){ 0.0f, 0.0f, 5.0f };
    f.camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    f.camera.fovy = 45.0f;
    f.camera.projection = CAMERA_PERSPECTIVE;
    float h = (float)(2.0*5.0*tan(22.5*PI_D/180.0));
    f.quad.size = (Vector2){ h*DECODE_W/DECODE_H*1.05f, h*1.05f };      // a little beyond every edge
    f.quad.origin = (Vector2){ f.quad.size.x*0.5f, f.quad.size.y*0.5f };
    RblLight light;
    memset(&light, 0, sizeof(light));
    light.position = (Vector3){ 1.0f, 1.0f, 2.0f }; light.color = WHITE; light.intensity = 4.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &light; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    for (int e = 0; e < 4; e++)
    {
        RblMaterialSource src;
        memset(&src, 0, sizeof(src));
        src.albedo = albedo;
        if (encodings[e] != RBL_NORMAL_NONE) { src.normal = normalMap; src.normalEncoding = encodings[e]; }
        src.mipmaps = true;
        RblPackedMaterial packed;
        if (!RblPackMaterial(&src, &packed)) return false;
        f.material = LoadMaterialDefault();
        RblLoadPackedTextures(&packed, &f.material);
        RblLitShaderDesc desc;
        memset(&desc, 0, sizeof(desc));
        desc.material = packed.layout;
        Shader lit = RblLoadLitShader(desc);
        RblSetScene(&scene);
        f.material.shader = lit;
        BenchTiming timing = { 3, 15, 40, 3e9 };
        double median = 0.0;
        BenchMedianOfRuns(DecodeRun, &f, 1, timing, &median);
        ms[e] = median*1e-6;
        BenchCsvRow(SUITE, names[e], "ms_per_frame_1280x720", ms[e], "ms");
        if (e > 0) BenchCsvRow(SUITE, names[e], "decode_ns_per_pixel", (ms[e] - ms[0])*1e6/(DECODE_W*DECODE_H), "ns");
        RblUnloadLitShader(&lit);
        UnloadTexture(f.material.maps[MATERIAL_MAP_ALBEDO].texture);
        if (f.material.maps[MATERIAL_MAP_NORMAL].texture.id != 0) UnloadTexture(f.material.maps[MATERIAL_MAP_NORMAL].texture);
        MemFree(f.material.maps);
        RblUnloadPackedMaterial(&packed);
    }
    UnloadRenderTexture(f.target);
    RblClose();
    rtCloseContext();
    return true;
}

int main(void)
{
    double benchStart = BenchNowNs();
    SetTraceLogLevel(LOG_WARNING);

    // ---- normal sets ---------------------------------------------------------------------------
    const int atlasTexels = ATLAS_SIZE*ATLAS_SIZE;
    float *heights = BumpyHeights();
    Vector3 *bumpy = (Vector3 *)malloc((size_t)atlasTexels*sizeof(Vector3));
    for (int y = 0; y < ATLAS_SIZE; y++)
        for (int x = 0; x < ATLAS_SIZE; x++) bumpy[y*ATLAS_SIZE + x] = rbl__heightNormal(heights, ATLAS_SIZE, ATLAS_SIZE, x, y, HEIGHT_STRENGTH, true);
    NormalSet sets[3] = { { "hemisphere", HemisphereNormals(HEMISPHERE_COUNT), HEMISPHERE_COUNT },
                          { "bumpy_atlas", bumpy, atlasTexels }, { "random_atlas", CosineNormals(atlasTexels), atlasTexels } };
    double maxTilt = 0.0;
    for (int i = 0; i < atlasTexels; i++) maxTilt = fmax(maxTilt, acos(fmin(1.0, bumpy[i].z))*180.0/PI_D);

    const char *encName[4] = { "rgb8", "xy8", "hemioct8", "hemioct8_rounded" };
    const int encId[4] = { RBL_NORMAL_RGB, RBL_NORMAL_XY, RBL_NORMAL_HEMIOCT, -1 };
    RblNormalErrorStats err[3][4];
    for (int s = 0; s < 3; s++)
        for (int e = 0; e < 4; e++)
        {
            err[s][e] = (encId[e] >= 0)? RblMeasureNormalEncoding(encId[e], sets[s].normals, sets[s].count) : MeasureHemiOctRounded(sets[s].normals, sets[s].count);
            char name[64];
            snprintf(name, sizeof(name), "%s_%s", sets[s].name, encName[e]);
            BenchCsvRow(SUITE, name, "mean_deg", err[s][e].mean, "deg");
            BenchCsvRow(SUITE, name, "p99_deg", err[s][e].p99, "deg");
            BenchCsvRow(SUITE, name, "max_deg", err[s][e].max, "deg");
            BenchCsvRow(SUITE, name, "count", err[s][e].count, "normals");
        }

    // ---- source maps of the bumpy atlas ----------------------------------------------------------
    Image heightImg;
    memset(&heightImg, 0, sizeof(heightImg));
    heightImg.data = MemAlloc((unsigned int)(atlasTexels*sizeof(float)));
    memcpy(heightImg.data, heights, (size_t)atlasTexels*sizeof(float));
    heightImg.width = heightImg.height = ATLAS_SIZE;
    heightImg.mipmaps = 1;
    heightImg.format = PIXELFORMAT_UNCOMPRESSED_R32;
    Image normalMap = RblGenNormalMapFromHeight(heightImg, HEIGHT_STRENGTH, true);
    Image albedo = GenImageColor(ATLAS_SIZE, ATLAS_SIZE, WHITE);
    Image specular = GenImageColor(ATLAS_SIZE, ATLAS_SIZE, WHITE);
    Image emissiveGrey = GenImageColor(ATLAS_SIZE, ATLAS_SIZE, BLACK);
    for (int i = 0; i < atlasTexels; i++)
    {
        unsigned char *a = (unsigned char *)albedo.data + (size_t)i*4;
        int x = i%ATLAS_SIZE, y = i/ATLAS_SIZE, cell = (y/FRAME_PITCH)*FRAME_CELLS + x/FRAME_PITCH;
        a[0] = (unsigned char)(64 + (cell*37)%192); a[1] = (unsigned char)(64 + (cell*91)%192); a[2] = (unsigned char)(64 + (cell*53)%192);
        a[3] = (heights[i]*HEIGHT_STRENGTH > 1.0f)? 255 : 0;
        float spf = heights[i]*HEIGHT_STRENGTH*12.0f;
        unsigned char sp = (unsigned char)((spf > 255.0f)? 255.0f : (spf < 0.0f)? 0.0f : spf);
        unsigned char *s = (unsigned char *)specular.data + (size_t)i*4;
        s[0] = s[1] = s[2] = sp;
        if ((x + y)%97 < 5) { unsigned char *e = (unsigned char *)emissiveGrey.data + (size_t)i*4; e[0] = e[1] = e[2] = 200; }
    }
    ImageFormat(&specular, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    Image occlusion = RblGenOcclusionFromHeight(heightImg, 4, 8.0f);
    Image emissiveRgb = ImageCopy(emissiveGrey);
    ((unsigned char *)emissiveRgb.data)[2] = 1;        // one coloured texel: RGB layout
    ImageFormat(&emissiveGrey, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    Rectangle frames[FRAME_CELLS*FRAME_CELLS];
    for (int i = 0; i < FRAME_CELLS*FRAME_CELLS; i++)
        frames[i] = (Rectangle){ (float)((i%FRAME_CELLS)*FRAME_PITCH + FRAME_GUTTER), (float)((i/FRAME_CELLS)*FRAME_PITCH + FRAME_GUTTER),
                                 (float)(FRAME_PITCH - 2*FRAME_GUTTER), (float)(FRAME_PITCH - 2*FRAME_GUTTER) };

    // ---- bytes per texel -------------------------------------------------------------------------
    struct { const char *name; bool normal, specular, occlusion; int emissive; int encoding; } layouts[] = {
        { "albedo", false, false, false, 0, 0 },
        { "albedo_material", true, true, true, 0, 0 },
        { "albedo_material_mask", true, true, true, 1, 0 },
        { "albedo_material_emissive_rgb", true, true, true, 2, 0 },
        { "albedo_material_rgbnormal_mask", true, false, true, 1, RBL_NORMAL_RGB },
    };
    const int layoutCount = (int)(sizeof(layouts)/sizeof(layouts[0]));
    double packedBytes[8], packedBytesMips[8], separateBytes[8];
    for (int l = 0; l < layoutCount; l++)
    {
        RblMaterialSource src;
        memset(&src, 0, sizeof(src));
        src.albedo = albedo;
        if (layouts[l].normal) src.normal = normalMap;
        if (layouts[l].specular) src.specular = specular;
        if (layouts[l].occlusion) src.occlusion = occlusion;
        if (layouts[l].emissive) src.emissive = (layouts[l].emissive == 1)? emissiveGrey : emissiveRgb;
        src.normalEncoding = layouts[l].encoding;
        for (int mips = 0; mips < 2; mips++)
        {
            src.mipmaps = (mips == 1);
            RblPackedMaterial p;
            if (!RblPackMaterial(&src, &p)) { printf("bench_materials: pack failed\n"); return 1; }
            double b = (ImageBytes(p.albedo) + ImageBytes(p.material) + ImageBytes(p.emissive))/atlasTexels;
            if (mips) packedBytesMips[l] = b; else packedBytes[l] = b;
            RblUnloadPackedMaterial(&p);
        }
        separateBytes[l] = 4.0*(1 + layouts[l].normal + layouts[l].specular + layouts[l].occlusion + (layouts[l].emissive != 0));
        BenchCsvRow(SUITE, layouts[l].name, "packed_bytes_per_texel", packedBytes[l], "B");
        BenchCsvRow(SUITE, layouts[l].name, "packed_bytes_per_texel_mips", packedBytesMips[l], "B");
        BenchCsvRow(SUITE, layouts[l].name, "separate_rgba8_bytes_per_texel", separateBytes[l], "B");
    }
    BenchCsvRow(SUITE, "four_rgba8", "bytes_per_texel", 16.0, "B");

    // ---- pack time ---------------------------------------------------------------------------------
    const double mpixels = atlasTexels/1e6;
    const BenchTiming timing = { 1, 5, 21, 4e9 };
    const int packEnc[3] = { RBL_NORMAL_HEMIOCT, RBL_NORMAL_XY, RBL_NORMAL_RGB };
    const char *packEncName[3] = { "hemioct", "xy", "rgb" };
    double packMs[3][2][2];
    int packRuns[3][2][2];
    for (int e = 0; e < 3; e++)
        for (int mips = 0; mips < 2; mips++)
            for (int fr = 0; fr < 2; fr++)
            {
                RblMaterialSource src;
                memset(&src, 0, sizeof(src));
                src.albedo = albedo;
                src.normal = normalMap;
                if (packEnc[e] != RBL_NORMAL_RGB) src.specular = specular;
                src.occlusion = occlusion;
                src.emissive = emissiveGrey;
                src.normalEncoding = packEnc[e];
                src.mipmaps = (mips == 1);
                src.frames = fr? frames : NULL;
                src.frameCount = fr? FRAME_CELLS*FRAME_CELLS : 0;
                PackCase pc;
                memset(&pc, 0, sizeof(pc));
                pc.source = &src;
                double median;
                packRuns[e][mips][fr] = BenchMedianOfRuns(PackRun, &pc, 1, timing, &median);
                packMs[e][mips][fr] = median*1e-6/mpixels;
                char name[64];
                snprintf(name, sizeof(name), "pack_%s_%s_%s", packEncName[e], mips? "mips" : "nomips", fr? "frames" : "noframes");
                BenchCsvRow(SUITE, name, "ms_per_mpixel", packMs[e][mips][fr], "ms/MP");
                BenchCsvRow(SUITE, name, "runs", packRuns[e][mips][fr], "runs");
            }
    const char *genName[3] = { "gen_normal_from_height", "gen_height_from_luminance", "gen_occlusion_from_height" };
    double genMs[3];
    for (int g = 0; g < 3; g++)
    {
        GenCase gc = { g, heightImg, albedo };
        double median;
        BenchMedianOfRuns(GenRun, &gc, 1, timing, &median);
        genMs[g] = median*1e-6/mpixels;
        BenchCsvRow(SUITE, genName[g], "ms_per_mpixel", genMs[g], "ms/MP");
    }

    double decodeMs[4] = { 0 };
    bool decoded = DecodeCostRows(albedo, normalMap, decodeMs);

    // ---- summary -----------------------------------------------------------------------------------
    printf("materials: angular error of encode + decode, degrees (bumpy atlas tilts up to %.0f degrees)\n", maxTilt);
    printf("  %-13s %-17s %8s %8s %8s %9s\n", "set", "encoding", "mean", "p99", "max", "normals");
    for (int s = 0; s < 3; s++)
        for (int e = 0; e < 4; e++)
            printf("  %-13s %-17s %8.4f %8.4f %8.4f %9d\n", sets[s].name, encName[e], err[s][e].mean, err[s][e].p99, err[s][e].max, err[s][e].count);
    printf("  reference (uniform hemisphere): rgb8 0.17 / max 0.38, xy8 0.47 / max 5.8, hemioct8 precise 0.24 / max 0.55\n");
    printf("\nmaterials: bytes per texel (%dx%d atlas)\n", ATLAS_SIZE, ATLAS_SIZE);
    printf("  %-32s %8s %12s %16s\n", "layout", "packed", "packed+mips", "separate RGBA8");
    for (int l = 0; l < layoutCount; l++)
        printf("  %-32s %8.2f %12.2f %16.2f\n", layouts[l].name, packedBytes[l], packedBytesMips[l], separateBytes[l]);
    printf("  %-32s %8.2f   (albedo, normal, specular/occlusion, emissive)\n", "four RGBA8 textures", 16.0);
    printf("\nmaterials: RblPackMaterial time, ms per megapixel (%dx%d, every map; median of runs)\n", ATLAS_SIZE, ATLAS_SIZE);
    printf("  %-9s %14s %14s %14s %14s\n", "encoding", "plain", "frames", "mips", "mips+frames");
    for (int e = 0; e < 3; e++)
        printf("  %-9s %14.1f %14.1f %14.1f %14.1f\n", packEncName[e], packMs[e][0][0], packMs[e][0][1], packMs[e][1][0], packMs[e][1][1]);
    printf("  (rgb: no specular map, RBL_NORMAL_RGB cannot store it)\n");
    for (int g = 0; g < 3; g++) printf("  %-28s %8.1f ms per megapixel\n", genName[g], genMs[g]);
    if (decoded)
    {
        printf("\nmaterials: shader decode cost, full-screen quad at %dx%d, lit by one point light (GPU time incl. glFinish)\n", DECODE_W, DECODE_H);
        const char *dn[4] = { "albedo only", "+ rgb8 normal map", "+ xy8 packed", "+ hemioct8 packed" };
        for (int e = 0; e < 4; e++)
        {
            if (e == 0) printf("  %-20s %8.2f ms/frame\n", dn[e], decodeMs[e]);
            else printf("  %-20s %8.2f ms/frame  (%+.2f ns per pixel over albedo only)\n", dn[e], decodeMs[e], (decodeMs[e] - decodeMs[0])*1e6/(DECODE_W*DECODE_H));
        }
    }
    printf("bench_materials: done in %.1f s, rows in %s\n", (BenchNowNs() - benchStart)*1e-9, BenchCsvPath());

    for (int s = 0; s < 3; s++) free(sets[s].normals);
    free(heights);
    UnloadImage(heightImg); UnloadImage(normalMap); UnloadImage(albedo); UnloadImage(specular);
    UnloadImage(occlusion); UnloadImage(emissiveGrey); UnloadImage(emissiveRgb);
    return 0;
}
