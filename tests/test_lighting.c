// Forward lighting specification (GPU, headless): every light type, both BRDFs and the optional
// stages (fog, exposure, tonemap, gamma, hemispheric ambient, classic falloff, constant emission)
// against the double-precision reference in lighting_reference.h, pixel by pixel; the hard cases
// stay finite in float targets; variants compile once; a billboard and a raylib Mesh with the same
// transform render the same pixels. Included by test_gpu_main.c (after test_render.c).

#include "lighting_reference.h"

// glIsProgram / glIsTexture / ... through the context's loader (memcpy: ISO C has no
// object-to-function pointer cast)
static bool glIsObject(const char *query, unsigned int id)
{
    unsigned char (*is)(unsigned int) = NULL;
    void *p = rtGlProc(query);
    if (p == NULL) return false;
    memcpy(&is, &p, sizeof(p));
    return is(id) != 0;
}
static bool glIsProgramFn(unsigned int id) { return glIsObject("glIsProgram", id); }

#define LIT_TARGET 96
#define LIT_PLANE 40.0f         // plane z = 0 centred at the origin, facing +Z (fixed billboard)

typedef struct LitScene {
    RblLitShaderDesc desc;
    RblLight lights[RBL_MAX_LIGHTS];
    int count;
    RefEnvironment env;
    Color albedo;
    bool normalMap;             // RGB normal map (desc.material.normalEncoding = RBL_NORMAL_RGB) of one texel
    Color normal;
    Camera3D camera;
} LitScene;

static Camera3D litCamera(Vector3 position, Vector3 target)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = position; c.target = target; c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = 45.0f; c.projection = CAMERA_PERSPECTIVE;
    return c;
}
static Camera3D headOnCamera(void) { return litCamera((Vector3){ 0.0f, 0.0f, 4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }); }
// Eye 0.35 above the plane looking 8 units ahead: the surface is seen at 1 to 10 degrees
static Camera3D grazingCamera(void) { return litCamera((Vector3){ 0.0f, -6.0f, 0.35f }, (Vector3){ 0.0f, 2.0f, 0.0f }); }

static LitScene litScene(int brdf)
{
    LitScene s;
    memset(&s, 0, sizeof(s));
    s.desc.brdf = brdf;
    s.env.ambient = (Color){ 25, 25, 30, 255 };
    s.env.up = d3(0, 1, 0);
    s.albedo = (Color){ 200, 160, 120, 255 };
    s.camera = headOnCamera();
    return s;
}

static RblLight litPoint(Vector3 p, float intensity, float range)
{
    RblLight l;
    memset(&l, 0, sizeof(l));
    l.type = RBL_LIGHT_POINT; l.position = p; l.color = (Color){ 255, 240, 220, 255 }; l.intensity = intensity; l.range = range;
    return l;
}

static RblLight litDirectional(Vector3 direction, float intensity)
{
    RblLight l;
    memset(&l, 0, sizeof(l));
    l.type = RBL_LIGHT_DIRECTIONAL; l.direction = direction; l.color = WHITE; l.intensity = intensity;
    return l;
}

static RblLight litSpot(Vector3 p, Vector3 direction, float inner, float outer, float intensity)
{
    RblLight l = litPoint(p, intensity, 10.0f);
    l.type = RBL_LIGHT_SPOT; l.direction = direction; l.innerAngle = inner; l.outerAngle = outer;
    l.color = (Color){ 220, 235, 255, 255 };
    return l;
}

static RblBillboard litPlane(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ LIT_PLANE, LIT_PLANE };
    b.origin = (Vector2){ LIT_PLANE*0.5f, LIT_PLANE*0.5f };
    b.facing = RBL_FACING_FIXED;
    b.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    return b;
}

// ---- render targets -------------------------------------------------------------------------
// Colour target of a raylib pixel format (RGBA8, RGBA16F, RGBA32F) with a depth renderbuffer
static RenderTexture2D litTarget(int format)
{
    RenderTexture2D rt;
    memset(&rt, 0, sizeof(rt));
    rt.id = rlLoadFramebuffer();
    rt.texture.id = rlLoadTexture(NULL, LIT_TARGET, LIT_TARGET, format, 1);
    rt.texture.width = LIT_TARGET; rt.texture.height = LIT_TARGET; rt.texture.mipmaps = 1; rt.texture.format = format;
    rt.depth.id = rlLoadTextureDepth(LIT_TARGET, LIT_TARGET, true);
    rlFramebufferAttach(rt.id, rt.texture.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
    rlFramebufferAttach(rt.id, rt.depth.id, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_RENDERBUFFER, 0);
    RT_CHECK(rlFramebufferComplete(rt.id), "framebuffer of format %d incomplete", format);
    return rt;
}

static void litTargetUnload(RenderTexture2D rt)
{
    rlUnloadTexture(rt.texture.id);
    rlUnloadFramebuffer(rt.id);
}

// Half-float to float (finite check only needs exponent 31 = Inf/NaN, but decode for the values)
static float halfToFloat(unsigned short h)
{
    int e = (h >> 10) & 31, m = h & 1023;
    float v = (e == 0)? ldexpf((float)m, -24) : ((e == 31)? ((m == 0)? INFINITY : NAN) : ldexpf((float)(m | 1024), e - 25));
    return (h & 0x8000)? -v : v;
}

typedef struct LitRender {
    Image image;                // RGBA8 display output (top row first)
    float *linear;              // RGBA32F or RGBA16F output as floats (top row first), NULL unless asked
    RblLitShader lit;
    bool loaded;
} LitRender;

// Renders the scene's plane once into a target of the given format (0 = RGBA8 display image)
static LitRender litRender(const LitScene *sc, int floatFormat)
{
    LitRender out;
    memset(&out, 0, sizeof(out));
    RblLitShaderDesc desc = sc->desc;
    desc.maxLights = (sc->count > 0)? sc->count : 1;
    desc.lightFeatures = RblLightFeatures(sc->lights, sc->count);
    if (sc->normalMap) desc.material.normalEncoding = RBL_NORMAL_RGB;
    if (floatFormat != 0) desc.linearOutput = true;
    out.lit = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(out.lit), "variant failed to load");
    if (!RblIsLitShaderValid(out.lit)) return out;
    RT_CHECK(RblSetLights(&out.lit, sc->lights, sc->count, sc->env.ambient), "lights rejected");
    if (desc.hemisphereAmbient)
        RT_CHECK(RblSetHemisphereAmbient(&out.lit, sc->env.ambient, sc->env.ground, (Vector3){ (float)sc->env.up.x, (float)sc->env.up.y, (float)sc->env.up.z }), "hemisphere ambient rejected");
    Texture2D albedo = solidTexture(sc->albedo), normal = solidTexture(sc->normal);
    Material m = LoadMaterialDefault();
    m.shader = out.lit.shader;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    if (sc->normalMap) m.maps[MATERIAL_MAP_NORMAL].texture = normal;
    RenderTexture2D rt = (floatFormat != 0)? litTarget(floatFormat) : LoadRenderTexture(LIT_TARGET, LIT_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(sc->camera);
    RblDrawBillboard(sc->camera, m, litPlane());
    EndMode3D();
    EndTextureMode();
    if (floatFormat == 0) out.image = rtReadTarget(rt);
    else
    {
        void *raw = rlReadTexturePixels(rt.texture.id, LIT_TARGET, LIT_TARGET, floatFormat);
        out.linear = (float *)malloc(sizeof(float)*4*LIT_TARGET*LIT_TARGET);
        for (int y = 0; y < LIT_TARGET; y++)
            for (int i = 0; i < 4*LIT_TARGET; i++)
            {
                int src = (LIT_TARGET - 1 - y)*4*LIT_TARGET + i;       // GL rows start at the bottom
                out.linear[y*4*LIT_TARGET + i] = (floatFormat == PIXELFORMAT_UNCOMPRESSED_R16G16B16A16)?
                    halfToFloat(((unsigned short *)raw)[src]) : ((float *)raw)[src];
            }
        RL_FREE(raw);
    }
    if (floatFormat != 0) litTargetUnload(rt); else UnloadRenderTexture(rt);
    UnloadTexture(albedo); UnloadTexture(normal);
    MemFree(m.maps);
    out.loaded = true;
    return out;
}

static void litRenderUnload(LitRender *r)
{
    if (r->image.data != NULL) UnloadImage(r->image);
    free(r->linear);
    RblUnloadLitShader(r->lit);
    memset(r, 0, sizeof(*r));
}

// Surface the shader sees at world point p: the decoded map normal (as RblDecodeNormal), the albedo texel
static RefSurface litSurface(const LitScene *sc, D3 p)
{
    RefSurface s;
    memset(&s, 0, sizeof(s));
    s.position = p;
    s.normal = d3(0, 0, 1);
    if (sc->normalMap)
    {
        D3 e = d3(sc->normal.r/255.0*2.0 - 1.0, sc->normal.g/255.0*2.0 - 1.0, sc->normal.b/255.0*2.0 - 1.0);
        if (dDot(e, e) >= 1.0/4096.0) s.normal = dNorm(e);      // T = +X, image up = +Y, N = +Z
    }
    s.albedo = refLinear(sc->albedo);
    s.specularMap = -1.0;
    s.occlusion = 1.0;
    return s;
}

typedef struct LitError { double max, mean, maxRaw, refMin, refMax; int pixels; } LitError;

// Display pixels against round(reference*255) over the interior of the plane (2% margin)
static LitError litCompare(const LitScene *sc, Image img)
{
    LitError e;
    memset(&e, 0, sizeof(e));
    e.refMin = 255.0;
    double sum = 0.0;
    RblLitShaderDesc d = sc->desc;
    for (int py = 1; py < LIT_TARGET - 1; py++)
        for (int px = 1; px < LIT_TARGET - 1; px++)
        {
            D3 p;
            if (!refPixelOnPlane(sc->camera, LIT_TARGET, LIT_TARGET, px, py, d3(0, 0, 0), d3(0, 0, 1), &p)) continue;
            if ((fabs(p.x) > LIT_PLANE*0.49) || (fabs(p.y) > LIT_PLANE*0.49)) continue;
            RefSurface s = litSurface(sc, p);
            RefRgb ref = refFinish(&d, refShade(&d, sc->lights, sc->count, &sc->env, &s, d3f(sc->camera.position)), p, d3f(sc->camera.position));
            Color c = rtPixel(img, px, py);
            const double got[3] = { c.r, c.g, c.b }, want[3] = { ref.r*255.0, ref.g*255.0, ref.b*255.0 };
            for (int ch = 0; ch < 3; ch++)
            {
                double q = fabs(got[ch] - floor(want[ch] + 0.5));
                double raw = fabs(got[ch] - want[ch]);
                if (q > e.max) e.max = q;
                if (raw > e.maxRaw) e.maxRaw = raw;
                e.refMin = fmin(e.refMin, want[ch]); e.refMax = fmax(e.refMax, want[ch]);
                sum += q;
            }
            e.pixels++;
        }
    e.mean = (e.pixels > 0)? sum/(3.0*e.pixels) : 0.0;
    return e;
}

// Renders display + float output, checks the float output is finite and the display matches the reference
static LitError litCheckAgainstReference(const LitScene *sc, const char *name, double maxTol, double meanTol)
{
    LitRender display = litRender(sc, 0);
    LitRender linear = litRender(sc, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32);
    LitError e;
    memset(&e, 0, sizeof(e));
    if (!display.loaded || !linear.loaded) { litRenderUnload(&display); litRenderUnload(&linear); RT_CHECK(false, "%s: render failed", name); return e; }
    int nonFinite = 0;
    for (int i = 0; i < 4*LIT_TARGET*LIT_TARGET; i++) if (!rtFinite(linear.linear[i]) || (linear.linear[i] < 0.0f)) nonFinite++;
    RT_CHECK(nonFinite == 0, "%s: %d float output values NaN/Inf/negative", name, nonFinite);
    e = litCompare(sc, display.image);
    RT_CHECK(e.pixels > LIT_TARGET*LIT_TARGET/8, "%s: only %d interior pixels compared", name, e.pixels);
    RT_CHECK(e.max <= maxTol && e.mean <= meanTol, "%s: error max %.0f mean %.3f /255 (allowed %.0f, %.2f)", name, e.max, e.mean, maxTol, meanTol);
    if (rtFailuresInCurrentTest() > 0) rtSaveImage(display.image, name);
    litRenderUnload(&display);
    litRenderUnload(&linear);
    return e;
}

// ---- variants -------------------------------------------------------------------------------
static void test_lighting_every_variant_in_the_matrix_compiles_links_and_compiles_once(void)
{
    int compiled = 0;
    for (int features = 1; features < 16; features++)
        for (int brdf = RBL_BRDF_LAMBERT; brdf <= RBL_BRDF_GGX; brdf++)
        {
            RblLitShaderDesc d;
            memset(&d, 0, sizeof(d));
            d.maxLights = 1 + (features*brdf)%RBL_MAX_LIGHTS;
            d.lightFeatures = features;
            d.brdf = brdf;
            d.fog.mode = (features + brdf)%4;
            d.fog.start = 1.0f; d.fog.end = 30.0f; d.fog.density = 0.05f;
            d.tonemap = features%3;
            d.hemisphereAmbient = (features & 1) != 0;
            d.instanced = (features & 2) != 0;
            d.material.normalEncoding = features%4;
            d.material.specular = (features%4 != RBL_NORMAL_RGB) && (brdf != RBL_BRDF_LAMBERT);
            d.material.occlusion = (features & 4) != 0;
            d.material.emissive = brdf;
            d.emissiveColor = (features & 8)? (Color){ 10, 20, 30, 255 } : BLANK;
            d.gamma = (features == 5)? 2.2f : 0.0f;
            RblLitShader a = RblLoadLitShader(d);
            RT_CHECK(RblIsLitShaderValid(a), "features %d brdf %d failed to compile", features, brdf);
            RblLitShader b = RblLoadLitShader(d);
            RT_CHECK(b.shader.id == a.shader.id, "identical desc compiled twice (%u, %u)", a.shader.id, b.shader.id);
            // Only what is asked for is compiled: absent features leave no uniform behind
            RT_CHECK((a.locLightSpot != -1) == ((features & RBL_LIGHTS_SPOT) != 0), "spot uniforms iff spot lights");
            RT_CHECK((a.locLightAttenuation != -1) == ((features & RBL_LIGHTS_CLASSIC_FALLOFF) != 0), "attenuation iff classic falloff");
            RT_CHECK((a.locFog != -1) == (d.fog.mode != RBL_FOG_NONE), "fog uniforms iff fog");
            RT_CHECK((a.locAmbientGround != -1) == d.hemisphereAmbient, "ground colour iff hemispheric ambient");
            RT_CHECK((a.locExposure != -1) == (d.tonemap != RBL_TONEMAP_NONE), "exposure iff tonemap (exposure 1)");
            RblUnloadLitShader(b);
            RT_CHECK(glIsProgramFn(a.shader.id), "unloading one holder freed the program another still uses");
            RblUnloadLitShader(a);
            rlDisableShader();          // raylib's SetShaderValue leaves the program bound; a bound program outlives delete
            RT_CHECK(!glIsProgramFn(a.shader.id), "program leaked after the last unload");
            compiled++;
        }
    printf("    %d variants compiled, linked, reused and released\n", compiled);
    // A different uniform-only value is a different program: materials never share state by accident
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.brdf = RBL_BRDF_GGX; d.roughness = 0.3f;
    RblLitShader a = RblLoadLitShader(d);
    d.roughness = 0.7f;
    RblLitShader b = RblLoadLitShader(d);
    RT_CHECK(a.shader.id != b.shader.id, "roughness 0.3 and 0.7 returned the same program");
    RblUnloadLitShader(a); RblUnloadLitShader(b);
}

static void test_lighting_bad_descs_and_lights_are_rejected_with_a_log_line(void)
{
    RblLitShaderDesc bad[10];
    memset(bad, 0, sizeof(bad));
    bad[0].brdf = 7; bad[1].roughness = 1.5f; bad[2].metalness = NAN; bad[3].fog.mode = RBL_FOG_LINEAR;  // end == start
    bad[4].tonemap = -1; bad[5].exposure = -1.0f; bad[6].lightFeatures = 16; bad[7].shininess = INFINITY;
    bad[8].fog.mode = RBL_FOG_EXP; bad[8].fog.density = -0.1f; bad[9].gamma = NAN;
    for (int i = 0; i < 10; i++)
    {
        warnings = 0;
        RblLitShader s = RblLoadLitShader(bad[i]);
        RT_CHECK(!RblIsLitShaderValid(s) && (warnings == 1), "bad desc %d: valid=%d warnings=%d", i, RblIsLitShaderValid(s), warnings);
    }
    // A point-only variant refuses spot/directional/classic lights; bad parameters never reach the shader
    LitScene sc = litScene(RBL_BRDF_LAMBERT);
    sc.lights[0] = litPoint((Vector3){ 0.5f, 0.5f, 1.0f }, 2.0f, 0.0f);
    sc.count = 1;
    LitRender before = litRender(&sc, 0);
    RblLight l[12];
    for (int i = 0; i < 12; i++) l[i] = sc.lights[0];
    l[0].type = RBL_LIGHT_SPOT; l[0].direction = (Vector3){ 0, 0, -1 };
    l[1].type = RBL_LIGHT_DIRECTIONAL; l[1].direction = (Vector3){ 0, 0, -1 };
    l[2].falloff = RBL_FALLOFF_CLASSIC;
    l[3].type = 9;
    l[4].intensity = NAN; l[5].intensity = -1.0f; l[6].range = -1.0f; l[7].position.z = INFINITY;
    l[8].intensity = 3e38f; l[8].color = WHITE;           // colour x intensity stays finite: accepted below
    l[9].falloff = -1; l[10].direction.x = NAN; l[11].intensity = INFINITY;
    for (int i = 0; i < 12; i++)
    {
        if (i == 8) continue;
        warnings = 0;
        RT_CHECK(!RblSetLights(&before.lit, &l[i], 1, BLACK) && (warnings == 1), "bad light %d accepted (warnings %d)", i, warnings);
    }
    // Directed lights need a direction and sane cones, in a variant compiled for them
    RblLitShaderDesc all;
    memset(&all, 0, sizeof(all));
    all.lightFeatures = RBL_LIGHTS_POINT | RBL_LIGHTS_DIRECTIONAL | RBL_LIGHTS_SPOT | RBL_LIGHTS_CLASSIC_FALLOFF;
    RblLitShader full = RblLoadLitShader(all);
    RblLight s[6];
    for (int i = 0; i < 6; i++) s[i] = litSpot((Vector3){ 0, 0, 2 }, (Vector3){ 0, 0, -1 }, 10.0f, 20.0f, 1.0f);
    s[0].direction = (Vector3){ 0, 0, 0 }; s[1].innerAngle = 30.0f; s[2].outerAngle = 95.0f; s[3].innerAngle = -1.0f;
    s[4].falloff = RBL_FALLOFF_CLASSIC; s[4].linear = -0.5f; s[5].type = RBL_LIGHT_DIRECTIONAL; s[5].direction = (Vector3){ 0, 0, 0 };
    for (int i = 0; i < 6; i++)
    {
        warnings = 0;
        RT_CHECK(!RblSetLights(&full, &s[i], 1, BLACK) && (warnings == 1), "bad directed light %d accepted (warnings %d)", i, warnings);
    }
    RblUnloadLitShader(full);
    // Nothing changed: same pixels as before the rejected calls
    RblLitShader keep = before.lit;
    LitRender after = litRender(&sc, 0);
    Color a = rtPixel(before.image, LIT_TARGET/2, LIT_TARGET/2), b = rtPixel(after.image, LIT_TARGET/2, LIT_TARGET/2);
    RT_CHECK((a.r == b.r) && (a.g == b.g) && (a.b == b.b), "rejected lights changed the image");
    (void)keep;
    litRenderUnload(&before); litRenderUnload(&after);
}

// ---- against the double reference -----------------------------------------------------------
static void test_lighting_matrix_matches_the_double_reference_within_2_of_255(void)
{
    const char *lightNames[4] = { "point near", "point far", "directional", "spot" };
    RblLight lights[4] = {
        litPoint((Vector3){ 0.4f, 0.3f, 0.8f }, 1.2f, 4.0f),
        litPoint((Vector3){ 3.0f, 2.0f, 9.0f }, 60.0f, 0.0f),
        litDirectional((Vector3){ -0.3f, -0.4f, -1.0f }, 1.0f),
        litSpot((Vector3){ 0.5f, 0.0f, 2.5f }, (Vector3){ -0.2f, 0.0f, -1.0f }, 10.0f, 25.0f, 8.0f),
    };
    struct { const char *name; int brdf; float shininess, roughness, metalness; } materials[10] = {
        { "blinn-phong n=16", RBL_BRDF_BLINN_PHONG, 16.0f, 0, 0 }, { "blinn-phong n=256", RBL_BRDF_BLINN_PHONG, 256.0f, 0, 0 },
        { "ggx r=0 m=0", RBL_BRDF_GGX, 0, 1e-6f, 0 }, { "ggx r=0 m=1", RBL_BRDF_GGX, 0, 1e-6f, 1 },
        { "ggx r=0.05 m=0", RBL_BRDF_GGX, 0, 0.05f, 0 }, { "ggx r=0.05 m=1", RBL_BRDF_GGX, 0, 0.05f, 1 },
        { "ggx r=0.5 m=0", RBL_BRDF_GGX, 0, 0.5f, 0 }, { "ggx r=0.5 m=1", RBL_BRDF_GGX, 0, 0.5f, 1 },
        { "ggx r=1 m=0", RBL_BRDF_GGX, 0, 1.0f, 0 }, { "ggx r=1 m=1", RBL_BRDF_GGX, 0, 1.0f, 1 },
    };
    printf("    %-18s %-12s %-8s %8s %8s %10s %7s %14s\n", "material", "light", "view", "max", "mean", "max(raw)", "pixels", "reference");
    double worstMax = 0.0, worstMean = 0.0;
    for (int mi = 0; mi < 10; mi++)
        for (int li = 0; li < 4; li++)
            for (int view = 0; view < 2; view++)
            {
                LitScene sc = litScene(materials[mi].brdf);
                sc.desc.shininess = materials[mi].shininess;
                sc.desc.roughness = materials[mi].roughness;
                sc.desc.metalness = materials[mi].metalness;
                sc.lights[0] = lights[li];
                sc.count = 1;
                sc.camera = view? grazingCamera() : headOnCamera();
                char name[96];
                snprintf(name, sizeof(name), "%s-%s-%s", materials[mi].name, lightNames[li], view? "grazing" : "head-on");
                for (char *c = name; *c; c++) if ((*c == ' ') || (*c == '=')) *c = '_';
                LitError e = litCheckAgainstReference(&sc, name, 2.0, 0.25);
                printf("    %-18s %-12s %-8s %8.0f %8.4f %10.2f %7d %6.1f..%5.1f\n", materials[mi].name, lightNames[li], view? "grazing" : "head-on", e.max, e.mean, e.maxRaw, e.pixels, e.refMin, e.refMax);
                if (e.max > worstMax) worstMax = e.max;
                if (e.mean > worstMean) worstMean = e.mean;
            }
    printf("    worst over the matrix: max %.0f/255, mean %.3f/255 (against the rounded reference)\n", worstMax, worstMean);
}

static void test_lighting_optional_stages_match_the_reference(void)
{
    struct { const char *name; int stage; } stages[] = {
        { "fog linear", 0 }, { "fog exp", 1 }, { "fog exp2", 2 }, { "reinhard exposure 2", 3 }, { "aces", 4 },
        { "gamma 2.2", 5 }, { "hemisphere ambient", 6 }, { "classic falloff", 7 }, { "classic range window", 8 },
        { "constant emission", 9 }, { "spot hard edge inner=outer", 10 }, { "blinn-phong coloured specular", 11 },
    };
    for (int i = 0; i < (int)(sizeof(stages)/sizeof(stages[0])); i++)
    {
        LitScene sc = litScene(RBL_BRDF_GGX);
        sc.desc.roughness = 0.4f;
        sc.lights[0] = litPoint((Vector3){ 0.4f, 0.3f, 1.0f }, 2.0f, 6.0f);
        sc.count = 1;
        sc.camera = grazingCamera();
        switch (stages[i].stage)
        {
            case 0: sc.desc.fog = (RblFog){ RBL_FOG_LINEAR, (Color){ 120, 130, 150, 255 }, 2.0f, 14.0f, 0.0f }; break;
            case 1: sc.desc.fog = (RblFog){ RBL_FOG_EXP, (Color){ 120, 130, 150, 255 }, 0.0f, 0.0f, 0.15f }; break;
            case 2: sc.desc.fog = (RblFog){ RBL_FOG_EXP2, (Color){ 120, 130, 150, 255 }, 0.0f, 0.0f, 0.12f }; break;
            case 3: sc.desc.tonemap = RBL_TONEMAP_REINHARD; sc.desc.exposure = 2.0f; break;
            case 4: sc.desc.tonemap = RBL_TONEMAP_ACES; sc.lights[0].intensity = 20.0f; break;
            case 5: sc.desc.gamma = 2.2f; break;
            case 6: sc.desc.hemisphereAmbient = true; sc.env.ambient = (Color){ 90, 120, 200, 255 }; sc.env.ground = (Color){ 80, 50, 20, 255 };
                    sc.env.up = d3(0.3, 0.2, 1.0); sc.normalMap = true; sc.normal = normalTexel(0.5f, 0.3f, 0.812f); break;
            case 7: sc.lights[0].falloff = RBL_FALLOFF_CLASSIC; sc.lights[0].constant = 1.0f; sc.lights[0].linear = 0.35f; sc.lights[0].quadratic = 0.44f;
                    sc.lights[0].range = 0.0f; sc.lights[0].intensity = 3.0f; break;
            case 8: sc.lights[0].falloff = RBL_FALLOFF_CLASSIC; sc.lights[0].quadratic = 1.0f; sc.lights[0].range = 3.0f; break;
            case 9: sc.desc.emissiveColor = (Color){ 60, 20, 0, 255 }; sc.desc.emissiveIntensity = 1.5f; break;
            case 10: sc.lights[0] = litSpot((Vector3){ 0.0f, 0.0f, 3.0f }, (Vector3){ 0.1f, 0.3f, -1.0f }, 20.0f, 20.0f, 9.0f); break;
            default: sc.desc.brdf = RBL_BRDF_BLINN_PHONG; sc.desc.specularColor = (Color){ 255, 200, 120, 255 }; sc.desc.specular = 0.8f; sc.desc.shininess = 40.0f;
                     sc.camera = headOnCamera(); break;
        }
        char name[64];
        snprintf(name, sizeof(name), "stage-%d", stages[i].stage);
        LitError e = litCheckAgainstReference(&sc, name, 2.0, 0.25);
        printf("    %-30s max %.0f mean %.4f /255 over %d pixels, reference %.1f..%.1f\n", stages[i].name, e.max, e.mean, e.pixels, e.refMin, e.refMax);
    }
}

// ---- hard cases: finite float output, display within 2/255 of the reference ----------------
static LitScene hardScene(int brdf)
{
    LitScene sc = litScene(brdf);
    sc.desc.roughness = 0.5f;
    sc.lights[0] = litPoint((Vector3){ 0.5f, 0.4f, 1.0f }, 2.0f, 8.0f);
    sc.count = 1;
    return sc;
}

static void hardCase(LitScene sc, const char *name)
{
    for (int brdf = RBL_BRDF_LAMBERT; brdf <= RBL_BRDF_GGX; brdf++)
    {
        sc.desc.brdf = brdf;
        char tag[96];
        snprintf(tag, sizeof(tag), "%s-brdf%d", name, brdf);
        LitError e = litCheckAgainstReference(&sc, tag, 2.0, 0.25);
        printf("    %-24s brdf %d: max %.0f mean %.4f /255, reference %.1f..%.1f\n", name, brdf, e.max, e.mean, e.refMin, e.refMax);
    }
}

static void test_lighting_hard_roughness_zero(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.desc.roughness = 1e-9f;      // below the 0.045 clamp: roughness 0
    sc.desc.shininess = 1e6f;       // Blinn-Phong's mirror
    hardCase(sc, "roughness 0");
}

static void test_lighting_hard_metal_with_black_albedo(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.desc.metalness = 1.0f;
    sc.albedo = BLACK;
    hardCase(sc, "metal black albedo");
}

static void test_lighting_hard_grazing_normal_ndotv_zero(void)
{
    // The normal map turns the normal to +X, perpendicular to the head-on view; light from +X
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.normalMap = true;
    sc.normal = (Color){ 255, 128, 128, 255 };
    sc.lights[0] = litPoint((Vector3){ 6.0f, 0.0f, 0.5f }, 30.0f, 0.0f);
    hardCase(sc, "ndotv 0");
}

static void test_lighting_hard_light_behind_the_surface(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.lights[0].position = (Vector3){ 0.2f, 0.1f, -1.0f };
    hardCase(sc, "light behind");
}

static void test_lighting_hard_light_on_the_shaded_point(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.lights[0] = litPoint((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, 0.0f);        // in the plane
    sc.lights[1] = litPoint((Vector3){ 0.3f, -0.2f, 1e-6f }, 1.0f, 0.0f);      // a hair above: distance clamp
    sc.count = 2;
    hardCase(sc, "light on the surface");
}

static void test_lighting_hard_range_zero_and_intensity_zero_and_zero_lights(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.lights[0].range = 0.0f;              // no window: plain inverse square
    hardCase(sc, "range 0");
    sc.lights[0].intensity = 0.0f;
    hardCase(sc, "intensity 0");
    sc.count = 0;
    hardCase(sc, "zero lights");
}

static void test_lighting_hard_maximum_light_count(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    unsigned int seed = 77u;
    for (int i = 0; i < RBL_MAX_LIGHTS; i++)
    {
        int type = i%3;
        Vector3 p = { rtRandomRange(&seed, -3.0f, 3.0f), rtRandomRange(&seed, -3.0f, 3.0f), rtRandomRange(&seed, 0.3f, 2.0f) };
        sc.lights[i] = (type == 0)? litPoint(p, 0.15f, 2.5f) : ((type == 1)? litSpot(p, (Vector3){ -p.x, -p.y, -p.z }, 5.0f, 35.0f, 0.4f) : litDirectional((Vector3){ -p.x, -p.y, -p.z }, 0.02f));
    }
    sc.count = RBL_MAX_LIGHTS;
    hardCase(sc, "64 lights");
}

static void test_lighting_hard_half_float_overflow_before_tonemap(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.lights[0] = litPoint((Vector3){ 0.3f, 0.2f, 0.05f }, 1e8f, 0.0f);       // radiance far above 65504
    sc.desc.tonemap = RBL_TONEMAP_ACES;
    hardCase(sc, "1e8 light ACES");
    sc.desc.tonemap = RBL_TONEMAP_REINHARD;
    hardCase(sc, "1e8 light Reinhard");
    // Linear output into a half-float target: clamped to the largest half, never Inf
    sc.desc.tonemap = RBL_TONEMAP_NONE;
    LitRender r = litRender(&sc, PIXELFORMAT_UNCOMPRESSED_R16G16B16A16);
    int bad = 0;
    float peak = 0.0f;
    for (int i = 0; (r.linear != NULL) && (i < 4*LIT_TARGET*LIT_TARGET); i++) { if (!rtFinite(r.linear[i])) bad++; else if (r.linear[i] > peak) peak = r.linear[i]; }
    RT_CHECK((r.linear != NULL) && (bad == 0), "%d half-float values Inf/NaN", bad);
    RT_CHECK(peak == 65504.0f, "peak %.1f: the hot spot should clamp to 65504", peak);
    printf("    half-float target: peak %.0f, %d non-finite\n", peak, bad);
    litRenderUnload(&r);
}

static void test_lighting_hard_zero_length_map_normal_is_the_flat_normal(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.normalMap = true;
    sc.normal = (Color){ 128, 128, 128, 255 };      // decodes to |n| = 0.004: the flat normal
    hardCase(sc, "zero map normal");
}

// ---- one shader for billboards and Models ---------------------------------------------------
// A fixed billboard and a raylib Mesh quad (GenMeshTangents) with the same transform, material and
// lights render the same pixels: the Model goes through DrawMesh with matModel/matNormal.
static void test_lighting_billboard_and_model_quad_render_identical_pixels(void)
{
    // Transform: rotate 35 degrees about (1, 1, 0), translate (0.3, -0.2, 0.5), scale 1.6 x 1.2
    Vector3 axis = Vector3Normalize((Vector3){ 1.0f, 1.0f, 0.0f });
    Matrix transform = MatrixMultiply(MatrixMultiply(MatrixScale(1.6f, 1.2f, 1.0f), MatrixRotate(axis, 35.0f*DEG2RAD)), MatrixTranslate(0.3f, -0.2f, 0.5f));
    // Unit quad in the XY plane facing +Z, UV (0,0) at the top-left like a billboard
    Mesh mesh;
    memset(&mesh, 0, sizeof(mesh));
    mesh.vertexCount = 4; mesh.triangleCount = 2;
    mesh.vertices = (float *)MemAlloc(sizeof(float)*12);
    mesh.texcoords = (float *)MemAlloc(sizeof(float)*8);
    mesh.normals = (float *)MemAlloc(sizeof(float)*12);
    mesh.indices = (unsigned short *)MemAlloc(sizeof(unsigned short)*6);
    const float v[12] = { -0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0 };
    const float uv[8] = { 0, 1, 1, 1, 1, 0, 0, 0 };
    const unsigned short idx[6] = { 0, 1, 2, 0, 2, 3 };
    memcpy(mesh.vertices, v, sizeof(v)); memcpy(mesh.texcoords, uv, sizeof(uv)); memcpy(mesh.indices, idx, sizeof(idx));
    for (int i = 0; i < 4; i++) { mesh.normals[i*3] = 0; mesh.normals[i*3 + 1] = 0; mesh.normals[i*3 + 2] = 1; }
    GenMeshTangents(&mesh);
    UploadMesh(&mesh, false);
    // The billboard: same centre, size, plane and orientation as the transformed quad
    Vector3 centre = Vector3Transform((Vector3){ 0, 0, 0 }, transform);
    Vector3 normal = Vector3Normalize(Vector3Subtract(Vector3Transform((Vector3){ 0, 0, 1 }, transform), centre));
    Vector3 up = Vector3Normalize(Vector3Subtract(Vector3Transform((Vector3){ 0, 1, 0 }, transform), centre));
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = centre; b.size = (Vector2){ 1.6f, 1.2f }; b.origin = (Vector2){ 0.8f, 0.6f };
    b.facing = RBL_FACING_FIXED; b.axis = normal; b.up = up;

    // A normal map tilted toward +U and image-up proves the tangent frames agree, not just the normals
    Image atlas = GenImageGradientLinear(8, 8, 45, (Color){ 240, 200, 150, 255 }, (Color){ 120, 180, 230, 255 });
    Texture2D albedo = LoadTextureFromImage(atlas);
    UnloadImage(atlas);
    Texture2D normalMap = solidTexture(normalTexel(0.45f, 0.3f, 0.841f));
    const int brdfs[2] = { RBL_BRDF_BLINN_PHONG, RBL_BRDF_GGX };
    for (int k = 0; k < 2; k++)
    {
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 3;
        d.lightFeatures = RBL_LIGHTS_POINT | RBL_LIGHTS_SPOT | RBL_LIGHTS_DIRECTIONAL;
        d.brdf = brdfs[k]; d.roughness = 0.35f; d.shininess = 48.0f;
        d.material.normalEncoding = RBL_NORMAL_RGB;
        d.fog = (RblFog){ RBL_FOG_EXP, (Color){ 40, 40, 60, 255 }, 0, 0, 0.05f };
        RblLitShader lit = RblLoadLitShader(d);
        RblLight lights[3] = {
            litPoint((Vector3){ 1.0f, 0.8f, 2.0f }, 3.0f, 8.0f),
            litSpot((Vector3){ -1.0f, 0.5f, 2.5f }, (Vector3){ 0.4f, -0.2f, -1.0f }, 10.0f, 30.0f, 6.0f),
            litDirectional((Vector3){ 0.2f, -0.5f, -1.0f }, 0.4f),
        };
        RT_CHECK(RblSetLights(&lit, lights, 3, (Color){ 30, 30, 35, 255 }), "lights rejected");
        Material m = LoadMaterialDefault();
        m.shader = lit.shader;
        m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
        m.maps[MATERIAL_MAP_NORMAL].texture = normalMap;
        Camera3D cam = litCamera((Vector3){ 0.6f, 0.5f, 3.0f }, (Vector3){ 0.2f, 0.0f, 0.0f });
        Image img[2];
        for (int path = 0; path < 2; path++)
        {
            RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
            BeginTextureMode(rt);
            ClearBackground(BLANK);
            BeginMode3D(cam);
            if (path == 0) RblDrawBillboard(cam, m, b); else DrawMesh(mesh, m, transform);
            EndMode3D();
            EndTextureMode();
            img[path] = rtReadTarget(rt);
            UnloadRenderTexture(rt);
        }
        int covered = 0, worst = 0, differ = 0;
        for (int y = 0; y < LIT_TARGET; y++)
            for (int x = 0; x < LIT_TARGET; x++)
            {
                Color a = rtPixel(img[0], x, y), c = rtPixel(img[1], x, y);
                if ((a.a == 0) || (c.a == 0)) { if (a.a != c.a) differ++; continue; }       // edges: coverage may differ by a pixel
                covered++;
                int e = abs(a.r - c.r); if (abs(a.g - c.g) > e) e = abs(a.g - c.g); if (abs(a.b - c.b) > e) e = abs(a.b - c.b);
                if (e > worst) worst = e;
            }
        printf("    brdf %d: %d pixels covered by both, worst difference %d/255, %d edge pixels covered by one\n", brdfs[k], covered, worst, differ);
        RT_CHECK(covered > 1500, "the quad covers only %d pixels", covered);
        RT_CHECK(worst <= 1, "billboard vs Model differ by %d/255", worst);
        RT_CHECK(differ <= 2*LIT_TARGET, "coverage differs in %d pixels", differ);
        if (rtFailuresInCurrentTest() > 0) { rtSaveImage(img[0], "billboard"); rtSaveImage(img[1], "model"); }
        UnloadImage(img[0]); UnloadImage(img[1]);
        MemFree(m.maps);
        RblUnloadLitShader(lit);
    }
    UnloadTexture(albedo); UnloadTexture(normalMap);
    UnloadMesh(mesh);
}
