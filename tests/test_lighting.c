// Forward lighting specification (GPU, headless): every light type, both BRDFs and the optional
// stages (fog, exposure, tonemap, gamma, hemispheric ambient, classic falloff, constant emission)
// against the double-precision reference in lighting_reference.h, pixel by pixel; the hard cases
// stay finite in float targets; variants compile once and materials that differ only in values share
// one program; a billboard and a raylib Mesh with the same transform render the same pixels.
// Programs hold compiled features only: per-material values travel with the Material drawn
// (rtSetMaterialValues), lights, ambient, fog and exposure with the scene (RblSetScene).
// The shader tests: every variant compiles, a failed compile is reported. Included by gpu_tests.h.

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

// Whether a linked program kept a uniform (glGetUniformLocation: silent, unlike GetShaderLocation)
static bool litHasUniform(Shader shader, const char *name)
{
    int (*get)(unsigned int, const char *) = NULL;
    void *p = rtGlProc("glGetUniformLocation");
    if (p == NULL) return false;
    memcpy(&get, &p, sizeof(p));
    return get(shader.id, name) != -1;
}

#define LIT_TARGET 96
#define LIT_PLANE 40.0f         // plane z = 0 centred at the origin, facing +Z (fixed billboard)

typedef struct LitScene {
    RblLitShaderDesc desc;      // compiled features (litRender adds maxLights, lightFeatures, fog mode, normal encoding, linear output)
    RtMaterialValues values;    // per-material values: the Material drawn with (rtSetMaterialValues)
    RblFog fog;                 // scene fog (the program compiles its mode in)
    float exposure;             // scene exposure (0 = 1)
    bool hemisphere;            // scene ambient is hemispheric: env.ground and env.up go to the scene (else flat)
    int maxLights;              // light slots compiled: 0 = count (at least 1), < 0 = the header's default (4)
    RblLight lights[RBL_MAX_LIGHTS];
    int count;
    RefEnvironment env;
    Color albedo;
    bool normalMap;             // RGB normal map (desc.material.normalEncoding = RBL_NORMAL_RGB) of one texel
    Color normal;
    Camera3D camera;
    int facing;                 // the plane's facing mode: RBL_FACING_FIXED (litScene's; +Z) or RBL_FACING_CAMERA_PLANE
    int path;                   // LIT_PATH_*: how the plane is drawn
    bool materialMap;           // bind `normal` as the material texture without a normal encoding (scalar channels only)
    int thickness;              // RblMaterialChannel of `normal` holding the card's thickness (transmission)
} LitScene;

enum { LIT_PATH_IMMEDIATE = 0, LIT_PATH_BATCHED, LIT_PATH_INSTANCED };

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
    s.desc.shading.brdf = brdf;
    s.env.ambient = (Color){ 25, 25, 30, 255 };
    s.env.up = d3(0, 1, 0);
    s.albedo = (Color){ 200, 160, 120, 255 };
    s.camera = headOnCamera();
    s.facing = RBL_FACING_FIXED;
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
// ---- program, scene and reference of a LitScene ---------------------------------------------
// Light slots the scene's program compiles
static int litSlots(const LitScene *sc)
{
    if (sc->maxLights < 0) return 4;                        // RblLitShaderDesc.maxLights 0: the header's default
    if (sc->maxLights > 0) return sc->maxLights;
    return (sc->count > 0)? sc->count : 1;
}

// Lights the program shades: the scene's first maxLights
static int litShadedCount(const LitScene *sc) { return (sc->count < litSlots(sc))? sc->count : litSlots(sc); }

// The program's desc: compiled features only
static RblLitShaderDesc litProgramDesc(const LitScene *sc, int floatFormat)
{
    RblLitShaderDesc desc = sc->desc;
    desc.maxLights = (sc->maxLights < 0)? 0 : litSlots(sc);
    desc.shading.lightFeatures = RblGetLightFeatures(sc->lights, sc->count);
    desc.shading.fog = sc->fog.mode;
    if (sc->normalMap) desc.material.normalEncoding = RBL_NORMAL_RGB;
    desc.material.thickness = sc->thickness;
    if (floatFormat != 0) desc.shading.linearOutput = true;
    if (sc->path == LIT_PATH_INSTANCED) desc.instanced = true;
    return desc;
}

// The scene's plane: litPlane in the scene's facing mode
static RblBillboard litSceneBillboard(const LitScene *sc)
{
    RblBillboard b = litPlane();
    b.facing = sc->facing;
    if (b.facing != RBL_FACING_FIXED) { b.axis = (Vector3){ 0.0f, 0.0f, 0.0f }; b.up = (Vector3){ 0.0f, 0.0f, 0.0f }; }
    return b;
}

// Draws the scene's plane on its path (inside BeginMode3D)
static void litDrawPlane(const LitScene *sc, Material m)
{
    RblBillboard b = litSceneBillboard(sc);
    if (sc->path == LIT_PATH_IMMEDIATE) { RblDrawBillboard(sc->camera, m, b); return; }
    if (sc->path == LIT_PATH_BATCHED)
    {
        RblBatch batch = RblLoadBatch(4);
        RblBeginBatch(&batch, sc->camera);
        RT_CHECK(RblBatchAdd(&batch, m, &b), "batch refused the plane");
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
        return;
    }
    RblInstanceBuffer ib = RblLoadInstanceBuffer(4);
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.position = b.position; in.size = b.size; in.origin = b.origin;
    RblInstancedDesc idesc;
    memset(&idesc, 0, sizeof(idesc));
    idesc.facing = b.facing; idesc.axis = b.axis; idesc.up = b.up;
    RT_CHECK(RblDrawInstanced(&ib, sc->camera, m, idesc, &in, 1) == 1, "instanced draw refused the plane");
    RblUnloadInstanceBuffer(&ib);
}

// The frame's scene: lights and flat ambient (0.3's RblSetLights), hemisphere (RblSetHemisphereAmbient,
// sky = the ambient colour) only when the scene asks for it, fog and exposure
static RblScene litSceneOf(const LitScene *sc)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = sc->lights;
    scene.lightCount = sc->count;
    scene.ambient = sc->env.ambient;
    if (sc->hemisphere)
    {
        scene.ambientGround = sc->env.ground;
        scene.ambientUp = (Vector3){ (float)sc->env.up.x, (float)sc->env.up.y, (float)sc->env.up.z };
    }
    scene.fog = sc->fog;
    scene.exposure = sc->exposure;
    return scene;
}

// What the double reference reads: the values 0.3's desc held, wherever 1.0 keeps them
static RefParams litShading(const LitScene *sc)
{
    RefParams d;
    memset(&d, 0, sizeof(d));
    d.brdf = sc->desc.shading.brdf;
    d.specular = sc->values.specular;
    d.shininess = sc->values.shininess;
    d.specularColor = sc->values.specularColor;
    d.roughness = sc->values.roughness;
    d.metalness = sc->values.metalness;
    d.emissiveColor = sc->values.emissiveColor;
    d.emissiveIntensity = sc->values.emissiveIntensity;
    d.hemisphereAmbient = sc->hemisphere;
    d.fog = sc->fog;
    d.tonemap = sc->desc.shading.tonemap;
    d.exposure = sc->exposure;
    d.gamma = sc->desc.shading.gamma;
    d.linearOutput = false;
    double thickness = (sc->thickness == RBL_CHANNEL_B)? sc->normal.b/255.0 : ((sc->thickness == RBL_CHANNEL_A)? sc->normal.a/255.0 : 0.0);
    d.transmission = sc->desc.transmission? refClamp(sc->values.transmission, 0.0, 1.0)*(1.0 - thickness) : 0.0;
    return d;
}

// ---- render targets -------------------------------------------------------------------------
// Colour target of a raylib pixel format (RGBA8, RGBA16F, RGBA32F) with a depth renderbuffer
static RenderTexture2D litTarget(int format)
{
    // ES 2 renders to half floats only (EXT_color_buffer_half_float); the linear output is clamped to
    // the half-float range anyway
    if ((rlGetVersion() == RL_OPENGL_ES_20) && (format == PIXELFORMAT_UNCOMPRESSED_R32G32B32A32)) format = PIXELFORMAT_UNCOMPRESSED_R16G16B16A16;
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

typedef struct LitRender {
    Image image;                // RGBA8 display output (top row first)
    float *linear;              // RGBA32F or RGBA16F output as floats (top row first), NULL unless asked
    Shader lit;
    bool loaded;
} LitRender;

// Renders the scene's plane once into a target of the given format (0 = RGBA8 display image);
// setScene false draws with the scene the programs already hold
// shared: a lit program the caller holds (drawn with, not unloaded: out.lit stays zero), else NULL
// for one of the render's own
static LitRender litRenderShared(const LitScene *sc, int floatFormat, bool setScene, const Shader *shared)
{
    LitRender out;
    memset(&out, 0, sizeof(out));
    RblLitShaderDesc desc = litProgramDesc(sc, floatFormat);
    if (shared == NULL) out.lit = RblLoadLitShader(desc);
    Shader lit = (shared != NULL)? *shared : out.lit;
    RT_CHECK(RblIsLitShaderValid(lit), "variant failed to load");
    if (!RblIsLitShaderValid(lit)) return out;
    if (setScene)
    {
        RblScene scene = litSceneOf(sc);
        RT_CHECK(RblSetScene(&scene), "scene rejected");
    }
    Texture2D albedo = solidTexture(sc->albedo), normal = solidTexture(sc->normal);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    rtSetMaterialValues(&m, sc->values);
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    if (sc->normalMap || sc->materialMap) m.maps[MATERIAL_MAP_NORMAL].texture = normal;
    RenderTexture2D rt = (floatFormat != 0)? litTarget(floatFormat) : LoadRenderTexture(LIT_TARGET, LIT_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(sc->camera);
    litDrawPlane(sc, m);
    EndMode3D();
    EndTextureMode();
    if (floatFormat == 0) out.image = rtReadTarget(rt);
    else
    {
        float *raw = rtReadFloatPixels(rt.texture.id, LIT_TARGET, LIT_TARGET);      // half floats widened exactly
        out.linear = (float *)malloc(sizeof(float)*4*LIT_TARGET*LIT_TARGET);
        for (int y = 0; y < LIT_TARGET; y++)
            for (int i = 0; i < 4*LIT_TARGET; i++)
            {
                int src = (LIT_TARGET - 1 - y)*4*LIT_TARGET + i;       // GL rows start at the bottom
                out.linear[y*4*LIT_TARGET + i] = (raw != NULL)? raw[src] : NAN;
            }
        free(raw);
    }
    if (floatFormat != 0) litTargetUnload(rt); else UnloadRenderTexture(rt);
    UnloadTexture(albedo); UnloadTexture(normal);
    MemFree(m.maps);
    out.loaded = true;
    return out;
}

static LitRender litRenderWith(const LitScene *sc, int floatFormat, bool setScene) { return litRenderShared(sc, floatFormat, setScene, NULL); }
static LitRender litRender(const LitScene *sc, int floatFormat) { return litRenderWith(sc, floatFormat, true); }

static void litRenderUnload(LitRender *r)
{
    if (r->image.data != NULL) UnloadImage(r->image);
    free(r->linear);
    RblUnloadLitShader(&r->lit);
    memset(r, 0, sizeof(*r));
}

// Pixels (RGBA) where two display images differ
static int litDifferingPixels(Image a, Image b)
{
    if ((a.data == NULL) || (b.data == NULL)) return LIT_TARGET*LIT_TARGET;
    int n = 0;
    for (int y = 0; y < LIT_TARGET; y++)
        for (int x = 0; x < LIT_TARGET; x++)
        {
            Color p = rtPixel(a, x, y), q = rtPixel(b, x, y);
            n += (p.r != q.r) || (p.g != q.g) || (p.b != q.b) || (p.a != q.a);
        }
    return n;
}

// The scene's plane in world space (reference.h's refQuad): corner 0 (bottom-left), unit right R (+U of
// the texture), image-up U and normal N = R x U
typedef struct LitFrame { D3 origin, R, U, N; double width, height; } LitFrame;
static LitFrame litFrame(const LitScene *sc)
{
    RblBillboard b = litSceneBillboard(sc);
    D3 c[4], n;
    refQuad(sc->camera, &b, c, &n);
    LitFrame f;
    f.origin = c[0];
    f.width = dLen(dSub(c[1], c[0])); f.height = dLen(dSub(c[3], c[0]));
    f.R = dNorm(dSub(c[1], c[0])); f.U = dNorm(dSub(c[3], c[0])); f.N = n;
    return f;
}

// Surface the shader sees at world point p of the plane: the decoded map normal (as RblDecodeNormal) in
// the plane's tangent frame, the albedo texel. Seen from behind (the view vector on the -N side), the
// card is shaded as its mirror image through its plane: N flips, the in-plane (tangent) components of
// the map's normal stay.
static RefSurface litSurface(const LitScene *sc, D3 p)
{
    RefSurface s;
    memset(&s, 0, sizeof(s));
    s.position = p;
    LitFrame f = litFrame(sc);
    D3 n = (dDot(f.N, refViewVector(sc->camera, p)) < 0.0)? dScale(f.N, -1.0) : f.N;
    s.normal = n;
    if (sc->normalMap)
    {
        D3 e = d3(sc->normal.r/255.0*2.0 - 1.0, sc->normal.g/255.0*2.0 - 1.0, sc->normal.b/255.0*2.0 - 1.0);
        if (dDot(e, e) >= 1.0/4096.0) s.normal = dNorm(dAdd(dAdd(dScale(f.R, e.x), dScale(f.U, e.y)), dScale(n, e.z)));
    }
    s.albedo = refLinear(sc->albedo);
    s.specularMap = -1.0;
    s.occlusion = 1.0;
    return s;
}

typedef struct LitError { double max, mean, maxRaw, refMin, refMax; int pixels; } LitError;

// Display pixels against round(reference*255) over the interior of the plane (2% margin); the
// reference shades the lights the program has slots for (the scene's first maxLights)
static LitError litCompare(const LitScene *sc, Image img)
{
    LitError e;
    memset(&e, 0, sizeof(e));
    e.refMin = 255.0;
    double sum = 0.0;
    RefParams d = litShading(sc);
    int shaded = litShadedCount(sc);
    LitFrame f = litFrame(sc);
    for (int py = 1; py < LIT_TARGET - 1; py++)
        for (int px = 1; px < LIT_TARGET - 1; px++)
        {
            D3 p;
            if (!refPixelOnPlane(sc->camera, LIT_TARGET, LIT_TARGET, px, py, f.origin, f.N, &p)) continue;
            double a = dDot(dSub(p, f.origin), f.R)/f.width, b = dDot(dSub(p, f.origin), f.U)/f.height;
            if ((a < 0.01) || (a > 0.99) || (b < 0.01) || (b > 0.99)) continue;
            RefSurface s = litSurface(sc, p);
            RefRgb ref = refFinishAt(&d, refShadeView(&d, sc->lights, shaded, &sc->env, &s, refViewVector(sc->camera, p)), refViewDistance(sc->camera, p));
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
static void test_lighting_every_variant_compiles_and_each_handle_owns_its_program(void)
{
    int compiled = 0;
    for (int features = 1; features < 16; features++)
        for (int brdf = RBL_BRDF_LAMBERT; brdf <= RBL_BRDF_GGX; brdf++)
        {
            RblLitShaderDesc d;
            memset(&d, 0, sizeof(d));
            d.maxLights = 1 + (features*brdf)%RBL_MAX_LIGHTS;
            d.shading.lightFeatures = features;
            d.shading.brdf = brdf;
            d.shading.fog = (features + brdf)%4;
            d.shading.tonemap = features%3;
            d.instanced = ((features & 2) != 0) && rtGlsl3();
            if (((features & 2) != 0) && !rtGlsl3())
            {
                // ES 2 / GL 2.1: the instanced variant is refused with one line naming the context
                RblLitShaderDesc i = d;
                i.instanced = true;
                warnings = 0;
                Shader refused = RblLoadLitShader(i);
                RT_CHECK((refused.id == 0) && (warnings == 1) && (strstr(lastWarning, "OpenGL 3.3 or ES 3") != NULL),
                         "instanced variant on a GLSL 1 context: id %u, %d log lines (%s)", refused.id, warnings, lastWarning);
            }
            d.material.normalEncoding = features%4;
            d.material.specular = (features%4 != RBL_NORMAL_RGB) && (brdf != RBL_BRDF_LAMBERT);
            d.material.occlusion = (features & 4) != 0;
            d.material.emissive = brdf;
            d.shading.gamma = (features == 5)? 2.2f : 0.0f;
            Shader a = RblLoadLitShader(d);
            RT_CHECK(RblIsLitShaderValid(a), "features %d brdf %d failed to compile", features, brdf);
            Shader b = RblLoadLitShader(d);
            RT_CHECK(RblIsLitShaderValid(b) && (b.id != a.id), "a second load of one desc shares the program (%u, %u): raylib's UnloadShader of one would delete both", a.id, b.id);
            // Only what is asked for is compiled: absent features leave no uniform behind
            RT_CHECK(litHasUniform(a, "rblLightSpot") == ((features & RBL_LIGHT_FEATURE_SPOT) != 0), "spot uniforms iff spot lights");
            RT_CHECK(litHasUniform(a, "rblLightAttenuation") == ((features & RBL_LIGHT_FEATURE_CLASSIC_FALLOFF) != 0), "attenuation iff classic falloff");
            RT_CHECK(litHasUniform(a, "rblFog") == (d.shading.fog != RBL_FOG_NONE), "fog uniforms iff fog");
            // Scene values reach every program: the hemisphere (the scene's ground colour) and the exposure
            // are compiled into every variant
            RT_CHECK(litHasUniform(a, "rblAmbientGround"), "ground colour in every variant (the scene picks flat or hemispheric ambient)");
            RT_CHECK(litHasUniform(a, "rblExposure"), "exposure in every variant (the scene's exposure)");
            unsigned int id = a.id, idB = b.id;
            RblUnloadLitShader(&b);
            RT_CHECK(b.id == 0, "RblUnloadLitShader left the holder's id %u", b.id);
            rlDisableShader();
            RT_CHECK(!glIsProgramFn(idB) && glIsProgramFn(id), "unloading one handle: its program %s, the other's %s", glIsProgramFn(idB)? "kept" : "deleted", glIsProgramFn(id)? "kept" : "deleted");
            RblUnloadLitShader(&a);
            rlDisableShader();          // raylib's SetShaderValue leaves the program bound; a bound program outlives delete
            RT_CHECK(!glIsProgramFn(id), "program leaked after the last unload");
            compiled++;
        }
    printf("    %d variants compiled, linked, reused and released\n", compiled);

    // Materials that differ only in values (roughness 0.3 and 0.7) share one program, and each draw
    // shows its own material's values: drawing one material never leaves state behind for the next
    LitScene s03 = litScene(RBL_BRDF_GGX), s07 = litScene(RBL_BRDF_GGX);
    s03.lights[0] = s07.lights[0] = litPoint((Vector3){ 0.5f, 0.4f, 1.0f }, 2.0f, 8.0f);
    s03.count = s07.count = 1;
    s03.values.roughness = 0.3f;
    s07.values.roughness = 0.7f;
    RblLitShaderDesc d03, d07;
    rbl__normaliseLitDesc(litProgramDesc(&s03, 0), &d03);      // padding zeroed: comparable bytes
    rbl__normaliseLitDesc(litProgramDesc(&s07, 0), &d07);
    RT_CHECK(memcmp(&d03, &d07, sizeof(d03)) == 0, "roughness 0.3 and 0.7 need different descs: values must not be compiled in");
    Shader a = RblLoadLitShader(d03);
    LitRender r03 = litRenderShared(&s03, 0, true, &a), r07 = litRenderShared(&s07, 0, true, &a), again = litRenderShared(&s03, 0, true, &a);
    int differ = litDifferingPixels(r03.image, r07.image), leaked = litDifferingPixels(r03.image, again.image);
    printf("    roughness 0.3 vs 0.7 through one program: %d pixels differ; 0.3 drawn again after 0.7: %d differ\n", differ, leaked);
    RT_CHECK(differ > LIT_TARGET*LIT_TARGET/50, "roughness 0.3 and 0.7 rendered alike (%d pixels differ): the material's value did not reach the draw", differ);
    RT_CHECK(leaked == 0, "the 0.3 material drawn after the 0.7 one differs in %d pixels (state leaked between materials)", leaked);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(r03.image, "r03"); rtSaveImage(r07.image, "r07"); rtSaveImage(again.image, "r03-again"); }
    litRenderUnload(&r03); litRenderUnload(&r07); litRenderUnload(&again);
    litCheckAgainstReference(&s03, "shared-r03", 2.0, 0.25);
    litCheckAgainstReference(&s07, "shared-r07", 2.0, 0.25);
    RblUnloadLitShader(&a);
}

static void test_lighting_bad_descs_and_lights_are_rejected_with_a_log_line(void)
{
    // Descs: only compiled features are left in them, and each is still checked
    RblLitShaderDesc bad[16];
    memset(bad, 0, sizeof(bad));
    bad[0].shading.brdf = 7; bad[1].maxLights = -1; bad[2].maxLights = RBL_MAX_LIGHTS + 1; bad[3].shading.fog = RBL_FOG_EXP2 + 1;
    bad[4].shading.tonemap = -1; bad[5].shading.fog = -1; bad[6].shading.lightFeatures = 16; bad[7].shading.tonemap = RBL_TONEMAP_ACES + 1;
    bad[8].shading.shadowMaps = RBL_MAX_SHADOWS + 1; bad[9].shading.gamma = NAN; bad[10].shading.shadowMaps = -1; bad[11].shading.shadowFilter = RBL_SHADOW_MAX_FILTER + 1;
    bad[12].shading.gamma = -1.0f; bad[13].material.normalEncoding = RBL_NORMAL_RGB + 1; bad[14].material.emissive = RBL_EMISSIVE_RGB + 1;
    bad[15].material.normalEncoding = RBL_NORMAL_RGB; bad[15].material.specular = true;
    for (int i = 0; i < 16; i++)
    {
        warnings = 0;
        Shader s = RblLoadLitShader(bad[i]);
        RT_CHECK(!RblIsLitShaderValid(s) && (s.id == 0) && (warnings == 1), "bad desc %d: valid=%d id=%u warnings=%d", i, RblIsLitShaderValid(s), s.id, warnings);
    }

    // Lights and scene values: RblSetScene refuses them with one log line and keeps the previous scene
    LitScene sc = litScene(RBL_BRDF_LAMBERT);
    sc.lights[0] = litPoint((Vector3){ 0.5f, 0.5f, 1.0f }, 2.0f, 0.0f);
    sc.count = 1;
    LitRender before = litRender(&sc, 0);           // point-only variant, scene set
    RblLight l[12];
    for (int i = 0; i < 12; i++) l[i] = sc.lights[0];
    l[0].type = RBL_LIGHT_SPOT; l[0].direction = (Vector3){ 0, 0, -1 };
    l[1].type = RBL_LIGHT_DIRECTIONAL; l[1].direction = (Vector3){ 0, 0, -1 };
    l[2].falloff = RBL_FALLOFF_CLASSIC;
    l[3].type = 9;
    l[4].intensity = NAN; l[5].intensity = -1.0f; l[6].range = -1.0f; l[7].position.z = INFINITY;
    l[8].intensity = 3e38f; l[8].color = WHITE;           // colour x intensity stays finite: not a bad light
    l[9].falloff = -1; l[10].direction.x = NAN; l[11].intensity = INFINITY;
    for (int i = 3; i < 12; i++)
    {
        if (i == 8) continue;
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = &l[i]; scene.lightCount = 1;
        warnings = 0;
        RT_CHECK(!RblSetScene(&scene) && (warnings == 1), "bad light %d accepted (warnings %d)", i, warnings);
    }
    // Directed lights need a direction and sane cones (checked as lights, whatever the programs compiled)
    RblLitShaderDesc all;
    memset(&all, 0, sizeof(all));
    all.shading.lightFeatures = RBL_LIGHT_FEATURE_POINT | RBL_LIGHT_FEATURE_DIRECTIONAL | RBL_LIGHT_FEATURE_SPOT | RBL_LIGHT_FEATURE_CLASSIC_FALLOFF;
    Shader full = RblLoadLitShader(all);
    RT_CHECK(RblIsLitShaderValid(full), "every-light-feature variant failed to load");
    RblLight s[6];
    for (int i = 0; i < 6; i++) s[i] = litSpot((Vector3){ 0, 0, 2 }, (Vector3){ 0, 0, -1 }, 10.0f, 20.0f, 1.0f);
    s[0].direction = (Vector3){ 0, 0, 0 }; s[1].innerAngle = 30.0f; s[2].outerAngle = 95.0f; s[3].innerAngle = -1.0f;
    s[4].falloff = RBL_FALLOFF_CLASSIC; s[4].linear = -0.5f; s[5].type = RBL_LIGHT_DIRECTIONAL; s[5].direction = (Vector3){ 0, 0, 0 };
    for (int i = 0; i < 6; i++)
    {
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = &s[i]; scene.lightCount = 1;
        warnings = 0;
        RT_CHECK(!RblSetScene(&scene) && (warnings == 1), "bad directed light %d accepted (warnings %d)", i, warnings);
    }
    // A bad light among good ones rejects the whole scene
    {
        RblLight mixed[3] = { sc.lights[0], l[4], sc.lights[0] };
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = mixed; scene.lightCount = 3;
        warnings = 0;
        RT_CHECK(!RblSetScene(&scene) && (warnings == 1), "a NaN light between good ones accepted (warnings %d)", warnings);
    }
    RblUnloadLitShader(&full);
    // Scene values that were desc values in 0.3: linear fog with end == start, negative fog density, negative exposure
    RblScene badScene[3];
    memset(badScene, 0, sizeof(badScene));
    for (int i = 0; i < 3; i++) { badScene[i].lights = sc.lights; badScene[i].lightCount = 1; badScene[i].ambient = sc.env.ambient; }
    badScene[0].fog.mode = RBL_FOG_LINEAR;                                      // end == start
    badScene[1].fog.mode = RBL_FOG_EXP; badScene[1].fog.density = -0.1f;
    badScene[2].exposure = -1.0f;
    for (int i = 0; i < 3; i++)
    {
        warnings = 0;
        RT_CHECK(!RblSetScene(&badScene[i]) && (warnings == 1), "bad scene %d accepted (warnings %d)", i, warnings);
    }
    // Nothing changed: the programs still hold the scene set before the rejected calls (same pixels)
    LitRender after = litRenderWith(&sc, 0, false);
    Color a = rtPixel(before.image, LIT_TARGET/2, LIT_TARGET/2), b = rtPixel(after.image, LIT_TARGET/2, LIT_TARGET/2);
    RT_CHECK((a.r == b.r) && (a.g == b.g) && (a.b == b.b), "rejected lights changed the image");
    int changed = litDifferingPixels(before.image, after.image);
    RT_CHECK(changed == 0, "rejected scenes changed %d pixels", changed);
    if (changed != 0) { rtSaveImage(before.image, "before"); rtSaveImage(after.image, "after"); }
    litRenderUnload(&after);

    // A light of a type or falloff the point-only program did not compile is not an error: the scene is
    // accepted and that program ignores the light with a log line (LOG_INFO: nothing is wrong) (ambient
    // black: the plane goes black)
    for (int i = 0; i < 3; i++)
    {
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = &l[i]; scene.lightCount = 1; scene.ambient = BLACK;
        warnings = 0;
        SetTraceLogLevel(LOG_INFO);
        bool accepted = RblSetScene(&scene);
        SetTraceLogLevel(LOG_WARNING);
        RT_CHECK(accepted && (warnings == 1), "light %d of a type the variant lacks: accepted=%d warnings=%d (expected accepted, one log line)", i, accepted, warnings);
        LitRender ignored = litRenderWith(&sc, 0, false);
        Color c = rtPixel(ignored.image, LIT_TARGET/2, LIT_TARGET/2);
        RT_CHECK((c.r == 0) && (c.g == 0) && (c.b == 0) && (c.a == 255), "light %d of a type the variant lacks lit the plane (%d,%d,%d,%d)", i, c.r, c.g, c.b, c.a);
        litRenderUnload(&ignored);
    }
    litRenderUnload(&before);

    // Bad values in a Material are not a load error any more: they are clamped or defaulted at draw
    // (0.3 rejected roughness 1.5, metalness NaN and shininess Inf in the desc): the draw stays finite
    // and renders as the clamped/default value does
    struct { const char *name; int brdf; RtMaterialValues bad, same; } values[3] = {
        { "roughness 1.5", RBL_BRDF_GGX, { .roughness = 1.5f }, { .roughness = 1.0f } },
        { "metalness NaN", RBL_BRDF_GGX, { .roughness = 0.4f, .metalness = NAN }, { .roughness = 0.4f } },
        { "shininess Inf", RBL_BRDF_BLINN_PHONG, { .shininess = INFINITY }, { .shininess = 0.0f } },
    };
    for (int i = 0; i < 3; i++)
    {
        LitScene v = litScene(values[i].brdf);
        v.lights[0] = litPoint((Vector3){ 0.3f, 0.2f, 1.0f }, 2.0f, 8.0f);
        v.count = 1;
        v.values = values[i].bad;
        LitRender got = litRender(&v, 0), linear = litRender(&v, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32);
        v.values = values[i].same;
        LitRender want = litRender(&v, 0);
        int nonFinite = 0;
        for (int k = 0; (linear.linear != NULL) && (k < 4*LIT_TARGET*LIT_TARGET); k++) nonFinite += !rtFinite(linear.linear[k]) || (linear.linear[k] < 0.0f);
        int differ = litDifferingPixels(got.image, want.image);
        printf("    material %-14s: %d float values non-finite, %d pixels differ from the clamped/default value\n", values[i].name, nonFinite, differ);
        RT_CHECK((linear.linear != NULL) && (nonFinite == 0), "material %s: %d float output values NaN/Inf/negative", values[i].name, nonFinite);
        RT_CHECK(differ == 0, "material %s: %d pixels differ from the clamped/default value", values[i].name, differ);
        litRenderUnload(&got); litRenderUnload(&linear); litRenderUnload(&want);
    }
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
                sc.values.shininess = materials[mi].shininess;
                sc.values.roughness = materials[mi].roughness;
                sc.values.metalness = materials[mi].metalness;
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
        sc.values.roughness = 0.4f;
        sc.lights[0] = litPoint((Vector3){ 0.4f, 0.3f, 1.0f }, 2.0f, 6.0f);
        sc.count = 1;
        sc.camera = grazingCamera();
        switch (stages[i].stage)
        {
            case 0: sc.fog = (RblFog){ RBL_FOG_LINEAR, (Color){ 120, 130, 150, 255 }, 2.0f, 14.0f, 0.0f }; break;
            case 1: sc.fog = (RblFog){ RBL_FOG_EXP, (Color){ 120, 130, 150, 255 }, 0.0f, 0.0f, 0.15f }; break;
            case 2: sc.fog = (RblFog){ RBL_FOG_EXP2, (Color){ 120, 130, 150, 255 }, 0.0f, 0.0f, 0.12f }; break;
            case 3: sc.desc.shading.tonemap = RBL_TONEMAP_REINHARD; sc.exposure = 2.0f; break;
            case 4: sc.desc.shading.tonemap = RBL_TONEMAP_ACES; sc.lights[0].intensity = 20.0f; break;
            case 5: sc.desc.shading.gamma = 2.2f; break;
            case 6: sc.hemisphere = true; sc.env.ambient = (Color){ 90, 120, 200, 255 }; sc.env.ground = (Color){ 80, 50, 20, 255 };
                    sc.env.up = d3(0.3, 0.2, 1.0); sc.normalMap = true; sc.normal = normalTexel(0.5f, 0.3f, 0.812f); break;
            case 7: sc.lights[0].falloff = RBL_FALLOFF_CLASSIC; sc.lights[0].constant = 1.0f; sc.lights[0].linear = 0.35f; sc.lights[0].quadratic = 0.44f;
                    sc.lights[0].range = 0.0f; sc.lights[0].intensity = 3.0f; break;
            case 8: sc.lights[0].falloff = RBL_FALLOFF_CLASSIC; sc.lights[0].quadratic = 1.0f; sc.lights[0].range = 3.0f; break;
            case 9: sc.values.emissiveColor = (Color){ 60, 20, 0, 255 }; sc.values.emissiveIntensity = 1.5f; break;
            case 10: sc.lights[0] = litSpot((Vector3){ 0.0f, 0.0f, 3.0f }, (Vector3){ 0.1f, 0.3f, -1.0f }, 20.0f, 20.0f, 9.0f); break;
            default: sc.desc.shading.brdf = RBL_BRDF_BLINN_PHONG; sc.values.specularColor = (Color){ 255, 200, 120, 255 }; sc.values.specular = 0.8f; sc.values.shininess = 40.0f;
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
    sc.values.roughness = 0.5f;
    sc.lights[0] = litPoint((Vector3){ 0.5f, 0.4f, 1.0f }, 2.0f, 8.0f);
    sc.count = 1;
    return sc;
}

static void hardCase(LitScene sc, const char *name)
{
    for (int brdf = RBL_BRDF_LAMBERT; brdf <= RBL_BRDF_GGX; brdf++)
    {
        sc.desc.shading.brdf = brdf;
        char tag[96];
        snprintf(tag, sizeof(tag), "%s-brdf%d", name, brdf);
        LitError e = litCheckAgainstReference(&sc, tag, 2.0, 0.25);
        printf("    %-24s brdf %d: max %.0f mean %.4f /255, reference %.1f..%.1f\n", name, brdf, e.max, e.mean, e.refMin, e.refMax);
    }
}

static void test_lighting_hard_roughness_zero(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.values.roughness = 1e-9f;    // below the 0.045 clamp: roughness 0
    sc.values.shininess = 1e6f;     // Blinn-Phong's mirror
    hardCase(sc, "roughness 0");
}

static void test_lighting_hard_metal_with_black_albedo(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.values.metalness = 1.0f;
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
    // A program lights the scene's first maxLights lights: more lights than slots is not an error (the
    // scene is accepted, one LOG_INFO line), and the reference shades just those first lights
    sc.maxLights = 17;
    hardCase(sc, "64 lights 17 slots");
    sc.maxLights = -1;                      // desc.maxLights 0: the default, 4 slots
    hardCase(sc, "64 lights default slots");
    Shader four = RblLoadLitShader(litProgramDesc(&sc, 0));
    RT_CHECK(RblIsLitShaderValid(four), "default-slot variant failed to load");
    RblScene scene = litSceneOf(&sc);
    warnings = 0;
    SetTraceLogLevel(LOG_INFO);
    bool accepted = RblSetScene(&scene);
    SetTraceLogLevel(LOG_WARNING);
    RT_CHECK(accepted && (warnings == 1), "64 lights for a 4-slot program: accepted=%d, %d log lines (expected accepted, one line)", accepted, warnings);
    RblUnloadLitShader(&four);
}

static void test_lighting_hard_half_float_overflow_before_tonemap(void)
{
    LitScene sc = hardScene(RBL_BRDF_GGX);
    sc.lights[0] = litPoint((Vector3){ 0.3f, 0.2f, 0.05f }, 1e8f, 0.0f);       // radiance far above 65504
    sc.desc.shading.tonemap = RBL_TONEMAP_ACES;
    hardCase(sc, "1e8 light ACES");
    sc.desc.shading.tonemap = RBL_TONEMAP_REINHARD;
    hardCase(sc, "1e8 light Reinhard");
    // Linear output into a half-float target: clamped to the largest half, never Inf
    sc.desc.shading.tonemap = RBL_TONEMAP_NONE;
    LitRender r = litRender(&sc, PIXELFORMAT_UNCOMPRESSED_R16G16B16A16);
    int bad = 0;
    float peak = 0.0f;
    for (int i = 0; (r.linear != NULL) && (i < 4*LIT_TARGET*LIT_TARGET); i++) { if (!rtFinite(r.linear[i])) bad++; else if (r.linear[i] > peak) peak = r.linear[i]; }
    RT_CHECK((r.linear != NULL) && (bad == 0), "%d half-float values Inf/NaN", bad);
    // raylib 6.0 on GL 2.1 allocates R16G16B16A16 as unsized GL_RGBA (8 bits): there the peak is 1
    bool halfTarget = (rlGetVersion() != RL_OPENGL_21);
    RT_CHECK(peak == (halfTarget? 65504.0f : 1.0f), "peak %.1f: the hot spot should clamp to %s", peak, halfTarget? "65504" : "1 (8-bit target)");
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
// scene render the same pixels: the Model goes through RblDrawMesh (the material's values, then
// raylib's DrawMesh with matModel/matNormal), and through plain DrawMesh, which reads the values the
// program last received.
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
        d.shading.lightFeatures = RBL_LIGHT_FEATURE_POINT | RBL_LIGHT_FEATURE_SPOT | RBL_LIGHT_FEATURE_DIRECTIONAL;
        d.shading.brdf = brdfs[k];
        d.material.normalEncoding = RBL_NORMAL_RGB;
        d.shading.fog = RBL_FOG_EXP;
        Shader lit = RblLoadLitShader(d);
        RblLight lights[3] = {
            litPoint((Vector3){ 1.0f, 0.8f, 2.0f }, 3.0f, 8.0f),
            litSpot((Vector3){ -1.0f, 0.5f, 2.5f }, (Vector3){ 0.4f, -0.2f, -1.0f }, 10.0f, 30.0f, 6.0f),
            litDirectional((Vector3){ 0.2f, -0.5f, -1.0f }, 0.4f),
        };
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = lights; scene.lightCount = 3; scene.ambient = (Color){ 30, 30, 35, 255 };
        scene.fog = (RblFog){ RBL_FOG_EXP, (Color){ 40, 40, 60, 255 }, 0, 0, 0.05f };
        RT_CHECK(RblSetScene(&scene), "scene rejected");
        Material m = LoadMaterialDefault();
        m.shader = lit;
        rtSetMaterialValues(&m, (RtMaterialValues){ .roughness = 0.35f, .shininess = 48.0f });
        m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
        m.maps[MATERIAL_MAP_NORMAL].texture = normalMap;
        Camera3D cam = litCamera((Vector3){ 0.6f, 0.5f, 3.0f }, (Vector3){ 0.2f, 0.0f, 0.0f });
        // Paths: the billboard; the Mesh through RblDrawMesh (uploads the material's values, then raylib's
        // DrawMesh); the Mesh through plain DrawMesh right after (reads the values last applied)
        Image img[3];
        for (int path = 0; path < 3; path++)
        {
            RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
            BeginTextureMode(rt);
            ClearBackground(BLANK);
            BeginMode3D(cam);
            if (path == 0) RblDrawBillboard(cam, m, b);
            else if (path == 1) RblDrawMesh(mesh, m, transform);
            else DrawMesh(mesh, m, transform);
            EndMode3D();
            EndTextureMode();
            img[path] = rtReadTarget(rt);
            UnloadRenderTexture(rt);
        }
        for (int path = 1; path < 3; path++)
        {
            int covered = 0, worst = 0, differ = 0;
            for (int y = 0; y < LIT_TARGET; y++)
                for (int x = 0; x < LIT_TARGET; x++)
                {
                    Color a = rtPixel(img[0], x, y), c = rtPixel(img[path], x, y);
                    if ((a.a == 0) || (c.a == 0)) { if (a.a != c.a) differ++; continue; }       // edges: coverage may differ by a pixel
                    covered++;
                    int e = abs(a.r - c.r); if (abs(a.g - c.g) > e) e = abs(a.g - c.g); if (abs(a.b - c.b) > e) e = abs(a.b - c.b);
                    if (e > worst) worst = e;
                }
            const char *how = (path == 1)? "RblDrawMesh" : "DrawMesh";
            printf("    brdf %d, %s: %d pixels covered by both, worst difference %d/255, %d edge pixels covered by one\n", brdfs[k], how, covered, worst, differ);
            RT_CHECK(covered > 1500, "%s: the quad covers only %d pixels", how, covered);
            RT_CHECK(worst <= 1, "billboard vs Model (%s) differ by %d/255", how, worst);
            RT_CHECK(differ <= 2*LIT_TARGET, "%s: coverage differs in %d pixels", how, differ);
        }
        if (rtFailuresInCurrentTest() > 0) { rtSaveImage(img[0], "billboard"); rtSaveImage(img[1], "model"); rtSaveImage(img[2], "model-drawmesh"); }
        UnloadImage(img[0]); UnloadImage(img[1]); UnloadImage(img[2]);
        MemFree(m.maps);
        RblUnloadLitShader(&lit);
    }
    UnloadTexture(albedo); UnloadTexture(normalMap);
    UnloadMesh(mesh);
}

// ---- programs compile; the lit billboard against an analytic Lambert, normal-map sides ----------
// ---- shaders ------------------------------------------------------------------------------------
static void test_shaders_every_lit_variant_compiles_and_links(void)
{
    const int lights[] = { 0, 1, 2, RBL_MAX_LIGHTS };
    for (int li = 0; li < 4; li++)
    for (int nm = 0; nm < 2; nm++)
    for (int inst = 0; inst < 2; inst++)
    {
        RblLitShaderDesc desc;
        memset(&desc, 0, sizeof(desc));
        desc.maxLights = lights[li];
        desc.material.normalEncoding = nm? RBL_NORMAL_RGB : RBL_NORMAL_NONE;
        desc.instanced = inst;
        if (inst && !rtGlsl3())
        {
            // ES 2 / GL 2.1 have no instancing: refused with one line, nothing compiled
            warnings = 0;
            Shader refused = RblLoadLitShader(desc);
            RT_CHECK((refused.id == 0) && (warnings == 1), "instanced variant on a GLSL 1 context: id %u, %d log lines", refused.id, warnings);
            continue;
        }
        Shader s = RblLoadLitShader(desc);
        RT_CHECK(RblIsLitShaderValid(s), "variant lights=%d normalMap=%d instanced=%d failed", lights[li], nm, inst);
        RT_CHECK(s.id != 0 && s.locs != NULL, "variant lights=%d normalMap=%d instanced=%d came back empty", lights[li], nm, inst);
        if (s.id == 0 || s.locs == NULL) continue;
        RT_CHECK(s.id != rlGetShaderIdDefault(), "variant fell back to raylib's default shader");
        RT_CHECK(rlGetLocationUniform(s.id, "rblLightPosition") != -1 && rlGetLocationUniform(s.id, "rblAmbient") != -1 &&
                 rlGetLocationUniform(s.id, "rblAlphaCutoff") != -1, "uniform locations missing");
        // The tangent is only an active attribute where a normal map uses it; then at raylib's location 4
        if (nm && !inst) RT_CHECK(s.locs[SHADER_LOC_VERTEX_TANGENT] == 4, "vertexTangent not at raylib's location 4 (%d)", s.locs[SHADER_LOC_VERTEX_TANGENT]);
        RT_CHECK((s.locs[SHADER_LOC_MAP_NORMAL] != -1) == (nm != 0), "normal map slot should exist only in the normal-map variant");
        RblUnloadLitShader(&s);
        RT_CHECK(s.id == 0 && s.locs == NULL, "RblUnloadLitShader did not zero the holder");
    }
}

static void test_shaders_compile_failure_is_reported_not_replaced_by_the_default(void)
{
    warnings = 0;
    const char *const broken[] = { "void main() { this is not glsl; }\n", NULL };
    const char *const *const parts[2] = { broken, NULL };
    Shader bad = rbl__loadShaderVariant(rbl__pass_lit_vs, parts, "");
    RT_CHECK(bad.id == 0, "a broken shader must come back invalid, not as raylib's default (id %u)", bad.id);
    // The internal step records why; its public caller logs that once under its own name
    RT_CHECK(warnings == 0 && strstr(rbl__state.problem, "failed to compile") != NULL, "internal step logged %d lines or recorded '%s'", warnings, rbl__state.problem);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = RBL_MAX_LIGHTS + 1;
    RT_CHECK(!RblIsLitShaderValid(RblLoadLitShader(desc)), "too many light slots must be refused");
    desc.maxLights = -1;
    RT_CHECK(!RblIsLitShaderValid(RblLoadLitShader(desc)), "negative light slots must be refused");
}

// ---- the lit billboard ---------------------------------------------------------------------------
static void test_lit_normal_map_tilted_toward_plus_u_is_brighter_lit_from_plus_u(void)
{
    Camera3D cam = frontCamera();
    const float tilt[2] = { 0.6f, -0.6f };      // the map tilts toward +U, then the mirrored map
    for (int k = 0; k < 2; k++)
    {
        Scene s = sceneLoad(WHITE, normalTexel(tilt[k], 0.0f, 0.8f), true);
        int lum[2];
        for (int side = 0; side < 2; side++)
        {
            RblLight l = rtPointLight((Vector3){ side? -3.0f : 3.0f, 0.0f, 1.0f }, 6.0f);
            RT_CHECK(renderSetLights(&l, 1, BLACK), "scene rejected");
            Image img = renderOne(&s, cam, centredQuad());
            lum[side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
            if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, side? "minusU" : "plusU");
            UnloadImage(img);
        }
        if (k == 0) RT_CHECK(lum[0] > lum[1] + 30, "tilt +U: lit from +U %d should beat lit from -U %d", lum[0], lum[1]);
        else RT_CHECK(lum[1] > lum[0] + 30, "tilt -U: lit from -U %d should beat lit from +U %d", lum[1], lum[0]);
        sceneUnload(s);
    }
    // The map's +Y is image-up: a map tilting up is brighter lit from above
    Scene s = sceneLoad(WHITE, normalTexel(0.0f, 0.6f, 0.8f), true);
    int lum[2];
    for (int side = 0; side < 2; side++)
    {
        RblLight l = rtPointLight((Vector3){ 0.0f, side? -3.0f : 3.0f, 1.0f }, 6.0f);
        RT_CHECK(renderSetLights(&l, 1, BLACK), "scene rejected");
        Image img = renderOne(&s, cam, centredQuad());
        lum[side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
        UnloadImage(img);
    }
    RT_CHECK(lum[0] > lum[1] + 30, "tilt image-up: lit from above %d should beat from below %d", lum[0], lum[1]);
    sceneUnload(s);
}

// Double-precision Lambert at the world point seen through pixel (px, py) of the front camera
static double refLambertChannel(int px, int py, Vector3 lightPos, double lightColor, double intensity, double range,
                                double ambient, double albedo, const double nTangent[3])
{
    // Unproject the pixel centre onto the billboard plane z = 0 (camera at z = 5, fovy 45, square target)
    double t = tan(45.0*PI/360.0);
    double ndcX = ((px + 0.5)/TARGET)*2.0 - 1.0, ndcY = 1.0 - ((py + 0.5)/TARGET)*2.0;
    D3 p = d3(ndcX*t*5.0, ndcY*t*5.0, 0.0);
    // Tangent frame of an unflipped camera-facing quad: T = +X, +V = -Y (so image-up = +Y), N = +Z
    D3 n = dNorm(d3(nTangent[0], nTangent[1], nTangent[2]));
    D3 l = dSub(d3f(lightPos), p);
    double d2 = dDot(l, l);
    double ndotl = fmax(dDot(n, dNorm(l)), 0.0);
    double window = 1.0;
    if (range > 0.0) { double x2 = d2/(range*range); window = fmin(fmax(1.0 - x2*x2, 0.0), 1.0); window *= window; }
    // Colours are sRGB-authored: decoded to linear light, lit, encoded back for the RGBA8 target
    double e = srgbDecode(lightColor)*intensity*ndotl*window/fmax(d2, 1e-4);
    return srgbEncode(srgbDecode(albedo)*(srgbDecode(ambient) + e))*255.0;
}

static void test_lit_flat_normal_map_matches_analytic_lambert_within_2_of_255(void)
{
    Camera3D cam = frontCamera();
    const Color albedo = { 230, 180, 120, 255 };
    Color flat = normalTexel(0.0f, 0.0f, 1.0f);      // (128,128,255): decodes to a 0.3 degree tilt
    double decoded[3] = { flat.r/255.0*2.0 - 1.0, flat.g/255.0*2.0 - 1.0, flat.b/255.0*2.0 - 1.0 };
    double vertexOnly[3] = { 0.0, 0.0, 1.0 };
    for (int nm = 0; nm < 2; nm++)
    {
        Scene s = sceneLoad(albedo, flat, nm);
        RblLight l = rtPointLight((Vector3){ 0.7f, 0.4f, 1.5f }, 1.6f);
        l.color = (Color){ 255, 220, 160, 255 };
        l.range = 6.0f;
        Color ambient = { 30, 30, 30, 255 };
        RT_CHECK(renderSetLights(&l, 1, ambient), "lights rejected");
        Image img = renderOne(&s, cam, centredQuad());
        double worst = 0.0;
        const int probes[5][2] = { { 32, 32 }, { 31, 31 }, { 20, 40 }, { 44, 24 }, { 28, 36 } };
        for (int i = 0; i < 5; i++)
        {
            int px = probes[i][0], py = probes[i][1];
            Color c = rtPixel(img, px, py);
            const unsigned char got[3] = { c.r, c.g, c.b };
            const double lc[3] = { l.color.r/255.0, l.color.g/255.0, l.color.b/255.0 };
            const double al[3] = { albedo.r/255.0, albedo.g/255.0, albedo.b/255.0 };
            for (int ch = 0; ch < 3; ch++)
            {
                double ref = refLambertChannel(px, py, l.position, lc[ch], l.intensity, l.range, ambient.r/255.0, al[ch], nm? decoded : vertexOnly);
                double err = fabs(got[ch] - fmin(ref, 255.0));
                if (err > worst) worst = err;
                RT_CHECK(ref > 20.0 && ref < 235.0, "reference %f outside the informative range", ref);
            }
        }
        RT_CHECK(worst <= 2.0, "normalMap=%d: worst error %.2f/255 against the analytic Lambert", nm, worst);
        if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, nm? "flatmap" : "vertexnormal");
        UnloadImage(img);
        sceneUnload(s);
    }
}

// Under every flip and rotated frame a map tilted toward +U lights the world side the tangent names
static void test_lit_flips_and_rotated_frames_light_the_plus_u_side(void)
{
    Camera3D cam = frontCamera();
    Scene s = sceneLoad(WHITE, normalTexel(0.6f, 0.0f, 0.8f), true);
    RblCameraFrame view = RblGetCameraFrame(cam);
    for (int mask = 0; mask < 16; mask++)
    {
        RblBillboard b = centredQuad();
        if (mask & 1) b.size.x = -2.0f;
        if (mask & 2) b.size.y = -2.0f;
        if (mask & 4) b.source = (Rectangle){ 0, 0, -4, 4 };
        if (mask & 8) b.flags = RBL_FRAME_ROTATED;
        RblVertex q[4];
        RblBillboardVertices(&view, 4, 4, &b, q);
        Vector3 T = { q[0].tangent[0], q[0].tangent[1], q[0].tangent[2] };
        int lum[2];
        for (int side = 0; side < 2; side++)
        {
            float k = side? -3.0f : 3.0f;
            RblLight l = rtPointLight((Vector3){ T.x*k, T.y*k, 1.0f }, 6.0f);
            RT_CHECK(renderSetLights(&l, 1, BLACK), "scene rejected");
            Image img = renderOne(&s, cam, b);
            lum[side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
            UnloadImage(img);
        }
        RT_CHECK(lum[0] > lum[1] + 30, "mask %d (T = %.0f,%.0f,%.0f): +U side %d should beat -U side %d", mask, T.x, T.y, T.z, lum[0], lum[1]);
    }
    sceneUnload(s);
}

static void test_lit_bad_lights_are_rejected_and_change_nothing(void)
{
    Scene s = sceneLoad(WHITE, normalTexel(0, 0, 1), false);        // 2 light slots
    RblLight good = rtPointLight((Vector3){ 0, 0, 2 }, 2.0f);
    RT_CHECK(renderSetLights(&good, 1, BLACK), "good light rejected");
    Image before = renderOne(&s, frontCamera(), centredQuad());
    RblLight bad[5] = { good, good, good, good, good };
    bad[0].position.x = NAN; bad[1].intensity = -1.0f; bad[2].range = INFINITY; bad[3].intensity = NAN; bad[4].range = -2.0f;
    for (int i = 0; i < 5; i++)
    {
        warnings = 0;
        RT_CHECK(!renderSetLights(&bad[i], 1, WHITE), "bad light %d accepted", i);
        RT_CHECK(warnings == 1, "bad light %d: %d warnings", i, warnings);
    }
    // A bad light past the program's slots still rejects the scene (the G-buffer lights every one)
    RblLight tail[3] = { good, good, bad[0] };
    warnings = 0;
    RT_CHECK(!renderSetLights(tail, 3, WHITE), "bad light after the slots accepted");
    RT_CHECK(warnings == 1, "bad light after the slots: %d warnings", warnings);
    warnings = 0;
    RT_CHECK(!renderSetLights(&good, -1, WHITE), "negative light count accepted");
    RT_CHECK(!renderSetLights(NULL, 1, WHITE), "NULL lights accepted");
    RT_CHECK(warnings == 2, "%d warnings", warnings);
    Image after = renderOne(&s, frontCamera(), centredQuad());
    Color a = rtPixel(before, 32, 32), b = rtPixel(after, 32, 32);
    RT_CHECK(a.r == b.r && a.g == b.g && a.b == b.b, "rejected lights changed the image (%d vs %d)", a.r, b.r);
    // More lights than slots is no error: the program lights the first maxLights (here the good light
    // and a dark one, so the image is unchanged), the rest are ignored with one (info) log line naming it
    RblLight three[3] = { good, good, rtPointLight((Vector3){ 0.5f, 0.5f, 0.5f }, 50.0f) };
    three[1].intensity = 0.0f;
    char programName[32];
    snprintf(programName, sizeof(programName), "program %u ", s.lit.id);
    warnings = 0;
    lastWarning[0] = '\0';
    SetTraceLogLevel(LOG_INFO);
    RT_CHECK(renderSetLights(three, 3, BLACK), "more lights than slots rejected");
    SetTraceLogLevel(LOG_WARNING);
    RT_CHECK(warnings == 1 && strstr(lastWarning, programName) != NULL, "lights beyond the slots: %d log lines, want 1 naming %s(%s)", warnings, programName, lastWarning);
    Image capped = renderOne(&s, frontCamera(), centredQuad());
    Color c = rtPixel(capped, 32, 32);
    RT_CHECK(a.r == c.r && a.g == c.g && a.b == c.b, "a light beyond the slots changed the image (%d vs %d)", a.r, c.r);
    // Zero lights: ambient only; a light a hair in front of the surface hits the distance clamp and saturates
    RT_CHECK(renderSetLights(NULL, 0, (Color){ 64, 64, 64, 255 }), "zero lights rejected");
    Image amb = renderOne(&s, frontCamera(), centredQuad());
    RT_CHECK(abs(rtPixel(amb, 32, 32).r - 64) <= 1, "ambient only: %d", rtPixel(amb, 32, 32).r);
    RblLight onSurface = rtPointLight((Vector3){ 0.0f, 0.0f, 1e-3f }, 1.0f);
    RT_CHECK(renderSetLights(&onSurface, 1, BLACK), "light on the surface rejected");
    Image hot = renderOne(&s, frontCamera(), centredQuad());
    RT_CHECK(rtPixel(hot, 32, 32).r == 255, "light on the surface should saturate, got %d", rtPixel(hot, 32, 32).r);
    UnloadImage(before); UnloadImage(after); UnloadImage(capped); UnloadImage(amb); UnloadImage(hot);
    sceneUnload(s);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_LIGHTING_TESTS \
    RT_TEST(test_shaders_every_lit_variant_compiles_and_links), \
    RT_TEST(test_shaders_compile_failure_is_reported_not_replaced_by_the_default), \
    RT_TEST(test_lit_normal_map_tilted_toward_plus_u_is_brighter_lit_from_plus_u), \
    RT_TEST(test_lit_flat_normal_map_matches_analytic_lambert_within_2_of_255), \
    RT_TEST(test_lit_flips_and_rotated_frames_light_the_plus_u_side), \
    RT_TEST(test_lit_bad_lights_are_rejected_and_change_nothing), \
    RT_TEST(test_lighting_every_variant_compiles_and_each_handle_owns_its_program), \
    RT_TEST(test_lighting_bad_descs_and_lights_are_rejected_with_a_log_line), \
    RT_TEST(test_lighting_matrix_matches_the_double_reference_within_2_of_255), \
    RT_TEST(test_lighting_optional_stages_match_the_reference), \
    RT_TEST(test_lighting_hard_roughness_zero), \
    RT_TEST(test_lighting_hard_metal_with_black_albedo), \
    RT_TEST(test_lighting_hard_grazing_normal_ndotv_zero), \
    RT_TEST(test_lighting_hard_light_behind_the_surface), \
    RT_TEST(test_lighting_hard_light_on_the_shaded_point), \
    RT_TEST(test_lighting_hard_range_zero_and_intensity_zero_and_zero_lights), \
    RT_TEST(test_lighting_hard_maximum_light_count), \
    RT_TEST(test_lighting_hard_half_float_overflow_before_tonemap), \
    RT_TEST(test_lighting_hard_zero_length_map_normal_is_the_flat_normal), \
    RT_TEST(test_lighting_billboard_and_model_quad_render_identical_pixels)
