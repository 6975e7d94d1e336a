// Sprites never shadow themselves (GPU, headless; raylib's Y-up world). A 1 x 2 card standing on a
// floor, with a normal map that bends the normal up to 60 degrees, is lit by one shadowing light
// swept over azimuth 0..345 (15-degree steps; 0 = from the viewer's side, 90 = from +X) and
// elevation 5..85, directional, spot and point (an omni map), in every facing mode, pivot at the bottom or the centre,
// casters facing the light (default) or the camera. Each case is rendered with and without the
// sprite in the shadow pass (the floor casts in both):
//   self      the sprite's own pixels darkened by its own caster (goal 0)
//   contact   reported: against no shadow map at all, the floor's PCF footprint darkens the sprite's
//             base where it meets the floor (any PCF receiver meeting another surface does)
//   ground    floor pixels seen from above, classified dark/lit, against the analytic projection of
//             the caster card (its corners as the pass draws them, projected along the light in
//             double): none misclassified farther than the PCF footprint from the analytic edge
// Also: the sprite receives a crate's shadow where a double-precision ray test says it falls; a
// light passing over an AXIS sprite's axis moves its ground shadow continuously (no pop); the
// caster identity is the same on every path (batched, instanced) and survives any draw order.
// Included by gpu_tests.h after test_shadows.c.

#include <time.h>

#define SS_VIEW 48              // front view of the sprite (pixels)
#define SS_TOP 64               // top-down view of the floor window (pixels)
#define SS_WINDOW 6.0f          // floor window [-3, 3]^2 seen from above
#define SS_MAP 128
#define SS_RADIUS 4.4f          // directional focus around (0, 1, 0): covers the window's corners
#define SS_AMBIENT 40

// Wall-clock seconds (reported, never asserted)
static double ssSeconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9*(double)t.tv_nsec;
}

typedef struct SsVariant {
    int facing;                 // RblFacing
    bool centre;                // pivot at the card's centre (else its bottom edge)
    bool faceCamera;            // casters face the billboard call's camera (else the light)
} SsVariant;

typedef struct SsRig {
    Shader lit;                 // receiver: one light, RGB normal map, one shadow map
    Material sprite, floor;
    Texture2D albedo, normal, flat;
    RblShadowMap maps[2];       // [faceCamera]
    RenderTexture2D front, top;
} SsRig;

static void ssSetCasterFacing(RblShadowDesc *d, bool faceCamera) { d->faceCamera = faceCamera; }

// Toward-light unit vector at azimuth az (0 = +Z, the viewer's side; 90 = +X) and elevation el, degrees
static Vector3 ssToLight(double az, double el)
{
    double a = az*PI/180.0, e = el*PI/180.0;
    return (Vector3){ (float)(cos(e)*sin(a)), (float)sin(e), (float)(cos(e)*cos(a)) };
}

static Camera3D ssViewer(void)
{
    Camera3D c = litCamera((Vector3){ 0.0f, 1.5f, 6.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
    c.fovy = 28.0f;
    return c;
}

static Camera3D ssTopCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 20.0f, 0.0f }; c.target = (Vector3){ 0.0f, 0.0f, 0.0f }; c.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    c.fovy = SS_WINDOW; c.projection = CAMERA_ORTHOGRAPHIC;
    return c;
}

// Floor point (x, z) seen at pixel (px, py) of the top view (top row first: -z up the image)
static Vector2 ssFloorAt(int px, int py)
{
    float p = SS_WINDOW/SS_TOP;
    return (Vector2){ (px + 0.5f)*p - SS_WINDOW*0.5f, (py + 0.5f)*p - SS_WINDOW*0.5f };
}

static RblBillboard ssFloor(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 40.0f, 40.0f }; b.origin = (Vector2){ 20.0f, 20.0f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; b.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    return b;
}

static RblBillboard ssSprite(SsVariant v)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.0f, 2.0f };
    b.origin = v.centre? (Vector2){ 0.5f, 1.0f } : (Vector2){ 0.5f, 0.0f };
    b.position = v.centre? (Vector3){ 0.0f, 1.0f, 0.0f } : (Vector3){ 0.0f, 0.0f, 0.0f };
    b.facing = v.facing;
    if (v.facing == RBL_FACING_FIXED) { b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f }; }
    return b;
}

// A tangent-space normal map bending up to 60 degrees across the card and 30 along it (limbs,
// outlines: where the receiver's bias used to follow the bent normal), opaque white albedo
static Texture2D ssNormalTexture(void)
{
    Image img = GenImageColor(32, 64, (Color){ 128, 128, 255, 255 });
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 32; x++)
        {
            double u = (x + 0.5)/32.0, v = (y + 0.5)/64.0;
            double nx = 1.7*sin(2.0*PI*1.5*u), ny = 0.6*sin(2.0*PI*3.0*v), nz = 1.0;
            double l = sqrt(nx*nx + ny*ny + nz*nz);
            ImageDrawPixel(&img, x, y, (Color){ (unsigned char)lround((nx/l*0.5 + 0.5)*255.0), (unsigned char)lround((ny/l*0.5 + 0.5)*255.0),
                                                (unsigned char)lround((nz/l*0.5 + 0.5)*255.0), 255 });
        }
    Texture2D t = LoadTextureFromImage(img);
    UnloadImage(img);
    return t;
}

static RblLight ssLight(int type, Vector3 L)
{
    if (type == RBL_LIGHT_DIRECTIONAL) return litDirectional((Vector3){ -L.x, -L.y, -L.z }, 1.0f);
    if (type == RBL_LIGHT_POINT)
    {
        // Point light 5 units from the card's centre toward the light (omni map: six cube faces)
        RblLight l = litPoint((Vector3){ 5.0f*L.x, 1.0f + 5.0f*L.y, 5.0f*L.z }, 25.0f, 14.0f);
        l.color = WHITE;
        return l;
    }
    // Spot 5 units from the card's centre toward the light, aimed at it: irradiance about 1 there
    RblLight l = litSpot((Vector3){ 5.0f*L.x, 1.0f + 5.0f*L.y, 5.0f*L.z }, (Vector3){ -L.x, -L.y, -L.z }, 45.0f, 60.0f, 25.0f);
    l.color = WHITE; l.range = 14.0f;
    return l;
}

static bool ssRigLoadMaps(SsRig *r, int lightFeatures, int mapSize, bool omni)
{
    memset(r, 0, sizeof(*r));
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = lightFeatures; desc.shading.shadowMaps = 1;
    desc.material.normalEncoding = RBL_NORMAL_RGB;
    r->lit = RblLoadLitShader(desc);
    r->albedo = solidTexture(WHITE);
    r->normal = ssNormalTexture();
    r->flat = solidTexture((Color){ 128, 128, 255, 255 });
    r->sprite = LoadMaterialDefault();
    r->sprite.shader = r->lit;
    r->sprite.maps[MATERIAL_MAP_ALBEDO].texture = r->albedo;
    r->sprite.maps[MATERIAL_MAP_NORMAL].texture = r->normal;
    r->floor = LoadMaterialDefault();
    r->floor.shader = r->lit;
    r->floor.maps[MATERIAL_MAP_ALBEDO].texture = r->albedo;
    r->floor.maps[MATERIAL_MAP_NORMAL].texture = r->flat;
    for (int k = 0; k < 2; k++)
    {
        RblShadowDesc sd;
        memset(&sd, 0, sizeof(sd));
        sd.size = mapSize;
        sd.omni = omni;
        ssSetCasterFacing(&sd, k == 1);
        r->maps[k] = RblLoadShadowMap(sd);
    }
    r->front = LoadRenderTexture(SS_VIEW, SS_VIEW);
    r->top = LoadRenderTexture(SS_TOP, SS_TOP);
    return RblIsLitShaderValid(r->lit) && RblIsShadowMapValid(r->maps[0]) && RblIsShadowMapValid(r->maps[1]);
}

static bool ssRigLoad(SsRig *r, int lightFeatures, int mapSize) { return ssRigLoadMaps(r, lightFeatures, mapSize, false); }

static void ssRigUnload(SsRig *r)
{
    shClearScene();
    UnloadRenderTexture(r->front); UnloadRenderTexture(r->top);
    RblUnloadShadowMap(&r->maps[0]); RblUnloadShadowMap(&r->maps[1]);
    UnloadTexture(r->albedo); UnloadTexture(r->normal); UnloadTexture(r->flat);
    MemFree(r->sprite.maps); MemFree(r->floor.maps);
    RblUnloadLitShader(&r->lit);
}

typedef void (*SsExtraCaster)(void *ctx);

// Shadow pass of map for light (floor always; the sprite if asked; extra casters), then the scene
static void ssPass(SsRig *r, RblShadowMap *map, RblLight *light, SsVariant v, bool sprite, SsExtraCaster extra, void *ctx)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = light; scene.lightCount = 1; scene.ambient = (Color){ SS_AMBIENT, SS_AMBIENT, SS_AMBIENT, 255 };
    Camera3D viewer = ssViewer();
    // Every pass of the map (an omni map: its six cube faces), each drawing the same casters
    for (int pass = 0; pass < RblShadowMapPasses(*map); pass++)
    {
        RT_CHECK(RblBeginShadowMapPass(map, &scene, 0, pass, (Vector3){ 0.0f, 1.0f, 0.0f }, SS_RADIUS), "shadow pass %d refused", pass);
        RblDrawBillboard(viewer, r->floor, ssFloor());
        if (sprite) RblDrawBillboard(viewer, r->sprite, ssSprite(v));
        if (extra != NULL) extra(ctx);
        RblEndShadowMap(map);
    }
    scene.shadowMaps = map; scene.shadowMapCount = 1;
    RT_CHECK(RblSetScene(&scene), "scene rejected");
}

// The scene without any shadow map: what the sprite looks like when nothing shadows it
static void ssNoMap(RblLight *light)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = light; scene.lightCount = 1; scene.ambient = (Color){ SS_AMBIENT, SS_AMBIENT, SS_AMBIENT, 255 };
    RT_CHECK(RblSetScene(&scene), "scene rejected");
}

// The sprite alone seen by the viewer (background transparent: alpha is its coverage)
static Image ssFront(SsRig *r, SsVariant v)
{
    Camera3D viewer = ssViewer();
    BeginTextureMode(r->front);
    ClearBackground(BLANK);
    BeginMode3D(viewer);
    RblDrawBillboard(viewer, r->sprite, ssSprite(v));
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(r->front);
}

// The floor alone from above
static Image ssTop(SsRig *r)
{
    Camera3D top = ssTopCamera();
    BeginTextureMode(r->top);
    ClearBackground(BLANK);
    BeginMode3D(top);
    RblDrawBillboard(top, r->floor, ssFloor());
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(r->top);
}

// Sprite pixels darker with its own caster than without (by more than 2/255 in any channel), and the worst
typedef struct SsSelf { int covered, darkened, worst; } SsSelf;
static SsSelf ssSelfCompare(Image with, Image without)
{
    SsSelf s = { 0, 0, 0 };
    for (int y = 0; y < SS_VIEW; y++)
        for (int x = 0; x < SS_VIEW; x++)
        {
            Color a = rtPixel(with, x, y), b = rtPixel(without, x, y);
            if ((a.a < 255) || (b.a < 255)) continue;
            s.covered++;
            int d = (int)b.r - a.r;
            if ((int)b.g - a.g > d) d = (int)b.g - a.g;
            if ((int)b.b - a.b > d) d = (int)b.b - a.b;
            if (d > 2) s.darkened++;
            if (d > s.worst) s.worst = d;
        }
    return s;
}

// ---- the analytic ground shadow ------------------------------------------------------------------
typedef struct SsPoly { double x[12], z[12]; int n; } SsPoly;

// The caster quad as the pass draws it (the header's CPU corners under the pass's frame), clipped to
// y >= lo, projected along the light onto y = 0 in double
static SsPoly ssShadowPolygon(const RblShadowMap *map, const RblLight *light, Vector3 L, SsVariant v, double lo)
{
    SsPoly out;
    out.n = 0;
    RblCameraFrame view = v.faceCamera? RblGetCameraFrame(ssViewer()) : map->state->lightView;
    rbl__Cast cast = rbl__castOf(map);
    rbl__FrameCache cache;
    cache.facing = -1;
    RblVertex q[4];
    RblBillboard b = ssSprite(v);
    if (!rbl__billboardVertices(&view, &cast, &cache, 32, 64, &b, q)) return out;
    double p[12][3];
    int n = 0;
    for (int i = 0; i < 4; i++)
    {
        const float *a = q[i].position, *c = q[(i + 1)%4].position;
        if (a[1] >= lo) { p[n][0] = a[0]; p[n][1] = a[1]; p[n][2] = a[2]; n++; }
        if ((a[1] >= lo) != (c[1] >= lo))
        {
            double t = (a[1] - lo)/((double)a[1] - c[1]);
            for (int k = 0; k < 3; k++) p[n][k] = a[k] + t*((double)c[k] - a[k]);
            n++;
        }
    }
    for (int i = 0; i < n; i++)
    {
        double t;
        if (light->type == RBL_LIGHT_DIRECTIONAL) { t = p[i][1]/(double)L.y; out.x[i] = p[i][0] - t*L.x; out.z[i] = p[i][2] - t*L.z; }
        else        // spot and point: from the light's position
        {
            double s[3] = { light->position.x, light->position.y, light->position.z };
            if (p[i][1] >= s[1] - 1e-6) { out.n = 0; return out; }       // the card reaches the light's height: no bounded shadow
            t = s[1]/(s[1] - p[i][1]);
            out.x[i] = s[0] + (p[i][0] - s[0])*t; out.z[i] = s[2] + (p[i][2] - s[2])*t;
        }
    }
    out.n = n;
    return out;
}

// Where (x, z) lies against a convex polygon: -2 inside and farther than band from its boundary, -1
// inside within band, 1 outside within band, 2 outside and farther
static int ssPolyClass(const SsPoly *poly, double x, double z, double band)
{
    if (poly->n < 3) return 2;
    double best = 1e30, area = 0.0;
    for (int i = 0; i < poly->n; i++)
    {
        int j = (i + 1)%poly->n;
        area += poly->x[i]*poly->z[j] - poly->x[j]*poly->z[i];
    }
    bool inside = fabs(area) > 1e-12;
    for (int i = 0; i < poly->n; i++)
    {
        int j = (i + 1)%poly->n;
        double ex = poly->x[j] - poly->x[i], ez = poly->z[j] - poly->z[i], px = x - poly->x[i], pz = z - poly->z[i];
        double ll = ex*ex + ez*ez, t = (ll > 0.0)? fmin(1.0, fmax(0.0, (px*ex + pz*ez)/ll)) : 0.0;
        double dx = px - t*ex, dz = pz - t*ez;
        best = fmin(best, dx*dx + dz*dz);
        if ((ex*pz - ez*px)*area < 0.0) inside = false;
    }
    return (inside? -1 : 1)*((best <= band*band)? 1 : 2);
}

// Floor pixels classified against the analytic shadow beyond the PCF footprint from its edge (k/2 +
// 1 = 2 texels, the normal offset, half a pixel each side: 2.5 texels + 1 pixel, the texel as the map
// has it there): dark inside the card's projection above the receiver's bias (inner), lit outside
// its projection above the floor (outer); dark = below the midpoint of this pixel's unshadowed value
// and the ambient floor
typedef struct SsGround { int wrong, darkPixels, analyticPixels, innerPixels, judged; double band; } SsGround;
static SsGround ssGroundCompare(Image shadowed, Image base, const SsPoly *inner, const SsPoly *poly, const RblShadowMap *map, const RblLight *light)
{
    SsGround g = { 0, 0, 0, 0, 0, 0.0 };
    for (int y = 0; y < SS_TOP; y++)
        for (int x = 0; x < SS_TOP; x++)
        {
            int b = rtPixel(base, x, y).r, s = rtPixel(shadowed, x, y).r;
            if (b < SS_AMBIENT + 40) continue;              // too dimly lit to tell (spot cone edge)
            bool dark = s < (b + SS_AMBIENT)/2;
            Vector2 f = ssFloorAt(x, y);
            // Only where the map covers the floor (a low sun's shadow runs past its focus: lit there);
            // an omni map covers every direction, its texel growing with the distance along the
            // face's axis (the major axis of the offset from the light)
            const Matrix *m = &map->state->matrix;
            double w = m->m3*f.x + m->m11*f.y + m->m15, u = (m->m0*f.x + m->m8*f.y + m->m12)/w, v = (m->m1*f.x + m->m9*f.y + m->m13)/w;
            double margin = 3.0/map->size;
            if (!map->desc.omni && (!(w > 0.0) || (u < margin) || (u > 1.0 - margin) || (v < margin) || (v > 1.0 - margin))) continue;
            double texel = map->state->texelWorld;
            if (light->type == RBL_LIGHT_POINT)
                texel *= fmax(fabs(f.x - light->position.x), fmax(fabs(light->position.y), fabs(f.y - light->position.z)));
            else if (light->type == RBL_LIGHT_SPOT)
            {
                Vector3 axis = map->state->lightView.back;
                texel *= -((f.x - light->position.x)*axis.x + (0.0 - light->position.y)*axis.y + (f.y - light->position.z)*axis.z);
            }
            double band = 2.5*texel + SS_WINDOW/SS_TOP;
            g.band = fmax(g.band, band);
            int d = ssPolyClass(poly, f.x, f.y, band), di = (dark || (d > 0))? 2 : ssPolyClass(inner, f.x, f.y, band);
            g.darkPixels += dark;
            g.analyticPixels += (d < 0);
            g.judged++;
            g.innerPixels += (d < 0) && (ssPolyClass(inner, f.x, f.y, 0.0) < 0);
            if ((dark && (d == 2)) || (!dark && (di == -2))) g.wrong++;
        }
    return g;
}

// Azimuth step of the sweep: 15 degrees on desktop GL 3.3 under EGL (tests/run.sh's first GPU run);
// the other contexts (OSMesa, ES 3, ES 2, GL 2.1, the browser) run every third direction, 45 degrees,
// to keep each context's run to a few seconds
static int ssAzimuthStep(void)
{
#ifdef __EMSCRIPTEN__
    return 45;
#else
    const char *ctx = getenv("RBL_TEST_CONTEXT");
    return ((ctx == NULL) || (strcmp(ctx, "egl") == 0))? 15 : 45;
#endif
}

static const char *const ssTypeNames[3] = { "directional", "spot", "point" };
static const int ssTypes[3] = { RBL_LIGHT_DIRECTIONAL, RBL_LIGHT_SPOT, RBL_LIGHT_POINT };
static const int ssFacings[4] = { RBL_FACING_CAMERA_PLANE, RBL_FACING_CAMERA_POSITION, RBL_FACING_AXIS, RBL_FACING_FIXED };
static const char *const ssFacingNames[4] = { "camera-plane", "camera-position", "axis", "fixed" };

// The sweep: every light direction x light type x facing x pivot x caster facing
static void test_shadows_sprites_never_shadow_themselves_in_a_sweep_of_every_light_direction(void)
{
    double t0 = ssSeconds();
    const int step = ssAzimuthStep(), directions = 5*(360/step);
    int cases = 0, selfCases = 0, selfWorst = 0, groundWrongCases = 0, judged = 0, contactCases = 0, contactWorst = 0, contactTop = SS_VIEW;
    double areaMin = 1e9, areaMax = 0.0;
    for (int type = 0; type < 3; type++)
    {
        int lightType = ssTypes[type];
        SsRig rig;
        RblLight probe = ssLight(lightType, ssToLight(0, 45));
        RT_CHECK(ssRigLoadMaps(&rig, RblGetLightFeatures(&probe, 1), SS_MAP, lightType == RBL_LIGHT_POINT), "rig failed to load");
        int typeSelf[4][2][2] = { { { 0 } } }, typeWorst[4][2][2] = { { { 0 } } };
        for (int el = 5; el <= 85; el += 20)
            for (int az = 0; az < 360; az += step)
            {
                Vector3 L = ssToLight(az, el);
                RblLight light = ssLight(lightType, L);
                // The unshadowed floor under this light (no caster but the floor itself)
                SsVariant none = { RBL_FACING_FIXED, false, false };
                ssPass(&rig, &rig.maps[0], &light, none, false, NULL, NULL);
                Image base = ssTop(&rig);
                for (int f = 0; f < 4; f++)
                    for (int centre = 0; centre < 2; centre++)
                    {
                        // Without the sprite in the pass the map holds the floor alone, whichever way
                        // casters face; and no map at all (the contact figures)
                        SsVariant v0 = { ssFacings[f], centre != 0, false };
                        ssPass(&rig, &rig.maps[0], &light, v0, false, NULL, NULL);
                        Image without = ssFront(&rig, v0);
                        ssNoMap(&light);
                        Image bare = ssFront(&rig, v0);
                        SsSelf contact = ssSelfCompare(without, bare);
                        contactCases += (contact.darkened > 0);
                        if (contact.worst > contactWorst) contactWorst = contact.worst;
                        for (int y = 0; y < SS_VIEW; y++)
                            for (int x = 0; x < SS_VIEW; x++)
                            {
                                Color a = rtPixel(without, x, y), b = rtPixel(bare, x, y);
                                if ((a.a == 255) && (b.a == 255) && ((int)b.r - a.r > 2)) contactTop = (y < contactTop)? y : contactTop;
                            }
                        UnloadImage(bare);
                        for (int cam = 0; cam < 2; cam++)
                        {
                            if ((ssFacings[f] == RBL_FACING_FIXED) && cam) continue;       // FIXED cards face neither
                            SsVariant v = { ssFacings[f], centre != 0, cam != 0 };
                            RblShadowMap *map = &rig.maps[cam];
                            ssPass(&rig, map, &light, v, true, NULL, NULL);
                            Image with = ssFront(&rig, v), top = ssTop(&rig);
                            SsSelf s = ssSelfCompare(with, without);
                            RT_CHECK(s.covered > 150, "%s %s az %d el %d: the sprite covers %d pixels only", ssFacingNames[f], ssTypeNames[type], az, el, s.covered);
                            if (s.darkened > 0) { selfCases++; typeSelf[f][centre][cam]++; }
                            if (s.worst > typeWorst[f][centre][cam]) typeWorst[f][centre][cam] = s.worst;
                            if (s.worst > selfWorst) selfWorst = s.worst;
                            // Ground: the analytic projection of the caster card, judged beyond the PCF
                            // footprint (k/2 + 1 texels, plus the normal offset and a pixel)
                            // Lower than the receiver's depth bias (along the light: texel (0.2 + 0.1 tan I),
                            // tan I <= 10, and the normal offset 0.25 texel sin I; I = 90 - elevation on the
                            // floor) a caster shows on the floor as nothing: twice that is the inner clip
                            double e = el*PI/180.0, texel = map->state->texelWorld;
                            if (lightType != RBL_LIGHT_DIRECTIONAL) texel *= sqrt(pow(light.position.x, 2) + pow(light.position.y - 1.0, 2) + pow(light.position.z, 2));
                            double hmin = 2.0*texel*(0.25*cos(e) + sin(e)*(0.2 + 0.1*fmin(cos(e)/sin(e), 10.0)));
                            SsPoly poly = ssShadowPolygon(map, &light, L, v, 0.0), inner = ssShadowPolygon(map, &light, L, v, hmin);
                            // (a card reaching the spot's height casts an unbounded shadow: not judged)
                            SsGround g = { 0, 0, 0, 0, 0, 0.0 };
                            if (poly.n >= 3)
                            {
                                g = ssGroundCompare(top, base, &inner, &poly, map, &light);
                                // Most of the window is lit and inside the map (a floor shadowing itself would leave nothing to judge)
                                RT_CHECK(g.judged > SS_TOP*SS_TOP/4, "%s az %d el %d: only %d floor pixels judged", ssTypeNames[type], az, el, g.judged);
                            }
                            if ((g.wrong > 0) && (groundWrongCases < 3))
                            {
                                printf("      polygon:");
                                for (int k = 0; k < poly.n; k++) printf(" (%.3f, %.3f)", poly.x[k], poly.z[k]);
                                printf("\n");
                            }
                            if (poly.n >= 3)
                            {
                                judged++;
                                if (g.wrong > 0) groundWrongCases++;
                                if ((g.analyticPixels >= 400) && (g.innerPixels > 0.9*g.analyticPixels))
                                {
                                    double ratio = (double)g.darkPixels/g.analyticPixels;
                                    areaMin = fmin(areaMin, ratio); areaMax = fmax(areaMax, ratio);
                                }
                            }
                            RT_CHECK(g.wrong == 0, "%s %s pivot %s casters %s, az %d el %d: %d floor pixels misclassified beyond %.3f of the analytic shadow",
                                     ssTypeNames[type], ssFacingNames[f], centre? "centre" : "bottom", cam? "camera" : "light", az, el, g.wrong, g.band);
                            if ((s.darkened > 0) && (typeSelf[f][centre][cam] == 1)) { rtSaveImage(with, "self-with"); rtSaveImage(without, "self-without"); }
                            if ((g.wrong > 0) && (groundWrongCases == 1)) rtSaveImage(top, "ground");
                            UnloadImage(with); UnloadImage(top);
                            cases++;
                        }
                        UnloadImage(without);
                    }
                UnloadImage(base);
            }
        for (int f = 0; f < 4; f++)
            for (int centre = 0; centre < 2; centre++)
                for (int cam = 0; cam < 2; cam++)
                {
                    if ((ssFacings[f] == RBL_FACING_FIXED) && cam) continue;
                    printf("    %-11s %-15s pivot %-6s casters face %-6s: %3d of %d directions self-darken, worst %3d/255\n", ssTypeNames[type],
                           ssFacingNames[f], centre? "centre" : "bottom", cam? "camera" : "light", typeSelf[f][centre][cam], directions, typeWorst[f][centre][cam]);
                    RT_CHECK(typeSelf[f][centre][cam] == 0, "%s %s pivot %s casters face %s: the sprite darkens itself in %d directions (worst %d/255)", ssTypeNames[type],
                             ssFacingNames[f], centre? "centre" : "bottom", cam? "camera" : "light", typeSelf[f][centre][cam], typeWorst[f][centre][cam]);
                }
        ssRigUnload(&rig);
    }
    printf("    azimuth 0..%d every %d degrees x elevation 5..85 every 20: %d cases: %d self-darken (worst %d/255); ground shadow vs the analytic caster card: %d of %d judged cases misclassify beyond the PCF band, area ratio %.3f..%.3f; %.1f s\n",
           360 - step, step, cases, selfCases, selfWorst, groundWrongCases, judged, areaMin, areaMax, ssSeconds() - t0);
    // The sprite's base spans rows 36..38 of the 48-row view: how high the floor's contact darkening reaches
    printf("    contact (the floor's PCF footprint, no map vs the floor alone in the pass): %d of %d sprite/light pairs darken, worst %d/255, highest darkened row %d (the card spans rows ~6..38)\n",
           contactCases, cases/(14)*8, contactWorst, contactTop);
}


// ---- receiving other casters: the user's scene -----------------------------------------------------
// An AXIS sprite (bottom pivot), the sun at 37 degrees elevation from +X (and 30 degrees either side),
// a crate (a raylib cube Model) between them: per pixel of the sprite, a double-precision ray toward
// the sun against the crate's box says where its shadow falls. Beyond the PCF footprint (2.5 texels
// and a pixel, as a distance from the box) every pixel inside is darkened to the ambient floor and
// every pixel outside keeps its unshadowed value, in both caster modes: the sprite receives the
// crate's shadow and never its own.
typedef struct SsCrate { Model model; Vector3 centre; float size; } SsCrate;
static void ssCrateCaster(void *ctx)
{
    SsCrate *c = (SsCrate *)ctx;
    RblDrawModel(c->model, c->centre, 1.0f, WHITE);
}

// Distance along the ray (o, d) to a box grown by g on every side (g < 0 shrinks it); < 0: missed
static double ssRayBox(const double o[3], const double d[3], const double lo[3], const double hi[3], double g)
{
    double t0 = 0.0, t1 = 1e30;
    for (int k = 0; k < 3; k++)
    {
        double a = lo[k] - g, b = hi[k] + g;
        if (fabs(d[k]) < 1e-12) { if ((o[k] < a) || (o[k] > b)) return -1.0; continue; }
        double u = (a - o[k])/d[k], v = (b - o[k])/d[k];
        t0 = fmax(t0, fmin(u, v)); t1 = fmin(t1, fmax(u, v));
    }
    return (t0 <= t1)? t0 : -1.0;
}

// World point of the visible card under front-view pixel (px, py) (the card faces the viewer about +Y)
static bool ssCardPoint(int px, int py, double out[3])
{
    Camera3D c = ssViewer();
    double e[3] = { c.position.x, c.position.y, c.position.z }, t[3] = { c.target.x, c.target.y, c.target.z };
    double f[3] = { t[0] - e[0], t[1] - e[1], t[2] - e[2] }, fl = sqrt(f[0]*f[0] + f[1]*f[1] + f[2]*f[2]);
    for (int k = 0; k < 3; k++) f[k] /= fl;
    double r[3] = { -f[2], 0.0, f[0] }, rl = sqrt(r[0]*r[0] + r[2]*r[2]);      // forward x +Y
    r[0] /= rl; r[2] /= rl;
    double u[3] = { r[1]*f[2] - r[2]*f[1], r[2]*f[0] - r[0]*f[2], r[0]*f[1] - r[1]*f[0] };
    double h = tan(c.fovy*0.5*PI/180.0), x = ((px + 0.5)/SS_VIEW*2.0 - 1.0)*h, y = (1.0 - (py + 0.5)/SS_VIEW*2.0)*h;
    double d[3] = { f[0] + r[0]*x + u[0]*y, f[1] + r[1]*x + u[1]*y, f[2] + r[2]*x + u[2]*y };
    // The card: through the origin, normal toward the eye off +Y
    double n[3] = { e[0], 0.0, e[2] }, nl = sqrt(n[0]*n[0] + n[2]*n[2]);
    n[0] /= nl; n[2] /= nl;
    double dn = d[0]*n[0] + d[2]*n[2];
    if (fabs(dn) < 1e-12) return false;
    double s = -(e[0]*n[0] + e[2]*n[2])/dn;
    for (int k = 0; k < 3; k++) out[k] = e[k] + d[k]*s;
    return true;
}

static void test_shadows_sprite_receives_a_crates_shadow_and_never_its_own_in_the_users_scene(void)
{
    SsRig rig;
    RblLight probe = ssLight(RBL_LIGHT_DIRECTIONAL, ssToLight(90, 37));
    RT_CHECK(ssRigLoad(&rig, RblGetLightFeatures(&probe, 1), 512), "rig failed to load");
    SsCrate crate;
    crate.size = 1.0f;
    crate.model = LoadModelFromMesh(GenMeshCube(crate.size, crate.size, crate.size));
    crate.model.materials[0].shader = rig.lit;
    const int azimuths[3] = { 60, 90, 120 };
    for (int a = 0; a < 3; a++)
        for (int cam = 0; cam < 2; cam++)
        {
            Vector3 L = ssToLight(azimuths[a], 37.0);
            RblLight light = ssLight(RBL_LIGHT_DIRECTIONAL, L);
            // The crate between the sun and the sprite's middle: its shadow's centre falls there
            crate.centre = (Vector3){ 1.6f*L.x, 1.0f + 1.6f*L.y, 1.6f*L.z };
            SsVariant v = { RBL_FACING_AXIS, false, cam != 0 };
            RblShadowMap *map = &rig.maps[cam];
            ssPass(&rig, map, &light, v, false, NULL, NULL);
            Image alone = ssFront(&rig, v);                         // the floor alone casts
            ssPass(&rig, map, &light, v, true, NULL, NULL);
            Image own = ssFront(&rig, v);                           // with its own caster
            ssPass(&rig, map, &light, v, true, ssCrateCaster, &crate);
            Image both = ssFront(&rig, v);                          // and the crate's
            double lo[3] = { crate.centre.x - 0.5*crate.size, crate.centre.y - 0.5*crate.size, crate.centre.z - 0.5*crate.size };
            double hi[3] = { crate.centre.x + 0.5*crate.size, crate.centre.y + 0.5*crate.size, crate.centre.z + 0.5*crate.size };
            double d[3] = { L.x, L.y, L.z }, band = 2.5*map->state->texelWorld + 3.0/SS_VIEW;   // a pixel is ~3/48 world units here
            int inside = 0, insideWrong = 0, outside = 0, outsideWrong = 0, selfWrong = 0, sprite = 0;
            for (int y = 0; y < SS_VIEW; y++)
                for (int x = 0; x < SS_VIEW; x++)
                {
                    Color c0 = rtPixel(alone, x, y), c1 = rtPixel(own, x, y), c2 = rtPixel(both, x, y);
                    if ((c0.a < 255) || (c2.a < 255)) continue;
                    sprite++;
                    if ((int)c0.r - c1.r > 2) selfWrong++;
                    double p[3];
                    if (!ssCardPoint(x, y, p)) continue;
                    if (c0.r < SS_AMBIENT + 30) continue;             // unlit there (bent normal away): nothing to darken
                    if (ssRayBox(p, d, lo, hi, -band) >= 0.0) { inside++; if (c2.r > SS_AMBIENT + 6) insideWrong++; }
                    else if (ssRayBox(p, d, lo, hi, band) < 0.0) { outside++; if (abs((int)c2.r - c1.r) > 2) outsideWrong++; }
                }
            const char *mode = cam? "camera-facing" : "light-facing";
            RT_CHECK(inside > sprite/10, "sun azimuth %d, %s casters: only %d of %d sprite pixels lie clearly in the crate's shadow (test setup)", azimuths[a], mode, inside, sprite);
            RT_CHECK(insideWrong == 0, "sun azimuth %d, %s casters: %d of %d pixels in the crate's shadow not darkened", azimuths[a], mode, insideWrong, inside);
            RT_CHECK(outsideWrong == 0, "sun azimuth %d, %s casters: %d of %d pixels outside the crate's shadow changed", azimuths[a], mode, outsideWrong, outside);
            RT_CHECK(selfWrong == 0, "sun azimuth %d, %s casters: %d pixels darkened by the sprite's own caster", azimuths[a], mode, selfWrong);
            printf("    sun azimuth %3d, elevation 37, %s casters: %d sprite pixels, %d (%.0f%%) in the crate's shadow all darkened, %d outside it unchanged, %d changed by its own caster\n",
                   azimuths[a], mode, sprite, inside, 100.0*inside/sprite, outside, selfWrong);
            if (rtFailuresInCurrentTest() > 0) { rtSaveImage(both, "crate"); rtSaveImage(alone, "alone"); }
            UnloadImage(alone); UnloadImage(own); UnloadImage(both);
        }
    crate.model.materials[0].shader = (Shader){ 0 };
    UnloadModel(crate.model);
    ssRigUnload(&rig);
}

// The same scene under a point light (an omni map): the lamp 4 units from the sprite's middle toward
// azimuth 60/90/120 at 37 degrees elevation, the crate between them; per pixel a double-precision
// segment from the card point to the lamp against the crate's box decides the shadow (beyond the
// PCF band: 2.5 texels at the lamp's distance along the face's axis, and a pixel)
static void test_shadows_sprite_receives_a_crates_shadow_under_a_point_light(void)
{
    SsRig rig;
    RblLight probe = ssLight(RBL_LIGHT_POINT, ssToLight(90, 37));
    RT_CHECK(ssRigLoadMaps(&rig, RblGetLightFeatures(&probe, 1), 512, true), "rig failed to load");
    SsCrate crate;
    crate.size = 0.5f;          // its shadow, magnified by the lamp's perspective, covers part of the card
    crate.model = LoadModelFromMesh(GenMeshCube(crate.size, crate.size, crate.size));
    crate.model.materials[0].shader = rig.lit;
    const int azimuths[3] = { 60, 90, 120 };
    for (int a = 0; a < 3; a++)
        for (int cam = 0; cam < 2; cam++)
        {
            Vector3 L = ssToLight(azimuths[a], 37.0);
            RblLight light = litPoint((Vector3){ 4.0f*L.x, 1.0f + 4.0f*L.y, 4.0f*L.z }, 10.0f, 14.0f);
            light.color = WHITE;
            crate.centre = (Vector3){ 1.6f*L.x, 1.0f + 1.6f*L.y, 1.6f*L.z };
            SsVariant v = { RBL_FACING_AXIS, false, cam != 0 };
            RblShadowMap *map = &rig.maps[cam];
            ssPass(&rig, map, &light, v, false, NULL, NULL);
            Image alone = ssFront(&rig, v);
            ssPass(&rig, map, &light, v, true, NULL, NULL);
            Image own = ssFront(&rig, v);
            ssPass(&rig, map, &light, v, true, ssCrateCaster, &crate);
            Image both = ssFront(&rig, v);
            double lo[3] = { crate.centre.x - 0.5*crate.size, crate.centre.y - 0.5*crate.size, crate.centre.z - 0.5*crate.size };
            double hi[3] = { crate.centre.x + 0.5*crate.size, crate.centre.y + 0.5*crate.size, crate.centre.z + 0.5*crate.size };
            double band = 2.5*map->state->texelWorld*4.0 + 3.0/SS_VIEW;
            int inside = 0, insideWrong = 0, outside = 0, outsideWrong = 0, selfWrong = 0, sprite = 0;
            for (int y = 0; y < SS_VIEW; y++)
                for (int x = 0; x < SS_VIEW; x++)
                {
                    Color c0 = rtPixel(alone, x, y), c1 = rtPixel(own, x, y), c2 = rtPixel(both, x, y);
                    if ((c0.a < 255) || (c2.a < 255)) continue;
                    sprite++;
                    if ((int)c0.r - c1.r > 2) selfWrong++;
                    double p[3];
                    if (!ssCardPoint(x, y, p)) continue;
                    if (c0.r < SS_AMBIENT + 30) continue;
                    // The segment to the lamp (parameter 0..1) against the box grown or shrunk by the band
                    double d[3] = { light.position.x - p[0], light.position.y - p[1], light.position.z - p[2] };
                    double tin = ssRayBox(p, d, lo, hi, -band), tout = ssRayBox(p, d, lo, hi, band);
                    if ((tin >= 0.0) && (tin <= 1.0)) { inside++; if (c2.r > SS_AMBIENT + 6) insideWrong++; }
                    else if ((tout < 0.0) || (tout > 1.0)) { outside++; if (abs((int)c2.r - c1.r) > 2) outsideWrong++; }
                }
            const char *mode = cam? "camera-facing" : "light-facing";
            RT_CHECK(inside > sprite/10, "lamp azimuth %d, %s casters: only %d of %d sprite pixels lie clearly in the crate's shadow (test setup)", azimuths[a], mode, inside, sprite);
            RT_CHECK(outside >= 16, "lamp azimuth %d, %s casters: only %d of %d sprite pixels lie clearly outside the crate's shadow (test setup)", azimuths[a], mode, outside, sprite);
            RT_CHECK(insideWrong == 0, "lamp azimuth %d, %s casters: %d of %d pixels in the crate's shadow not darkened", azimuths[a], mode, insideWrong, inside);
            RT_CHECK(outsideWrong == 0, "lamp azimuth %d, %s casters: %d of %d pixels outside the crate's shadow changed", azimuths[a], mode, outsideWrong, outside);
            RT_CHECK(selfWrong == 0, "lamp azimuth %d, %s casters: %d pixels darkened by the sprite's own caster", azimuths[a], mode, selfWrong);
            printf("    lamp azimuth %3d, elevation 37, %s casters: %d sprite pixels, %d (%.0f%%) in the crate's shadow all darkened, %d outside it unchanged, %d changed by its own caster\n",
                   azimuths[a], mode, sprite, inside, 100.0*inside/sprite, outside, selfWrong);
            if (rtFailuresInCurrentTest() > 0) { rtSaveImage(both, "crate-point"); rtSaveImage(alone, "alone-point"); }
            UnloadImage(alone); UnloadImage(own); UnloadImage(both);
        }
    crate.model.materials[0].shader = (Shader){ 0 };
    UnloadModel(crate.model);
    ssRigUnload(&rig);
}

// ---- continuity where the light sits on the sprite's axis ----------------------------------------
// A directional light passing over an AXIS sprite (axis +Y) from the front to behind, and from one side
// to the other, in 0.5-degree steps through the zenith: the ground shadow (floor pixels, top view)
// changes between neighbouring steps by no more than a few rows of pixels (a pop replaces most of its
// 100..250 pixels), with both caster modes. Near the axis the card turns about its mid-height line:
// its shadow is centred on it, the same whichever side the tilt leans to (light-facing cards turn
// round through the zenith by the documented fallback; camera-facing ones lean the other way once
// the light has crossed their plane).
static void test_shadows_light_over_an_axis_sprite_moves_its_shadow_continuously(void)
{
    SsRig rig;
    RblLight probe = ssLight(RBL_LIGHT_DIRECTIONAL, ssToLight(0, 45));
    RT_CHECK(ssRigLoad(&rig, RblGetLightFeatures(&probe, 1), SS_MAP), "rig failed to load");
    for (int cam = 0; cam < 2; cam++)
        for (int path = 0; path < 2; path++)        // over the front and back (azimuth 0 / 180), over the sides (90 / 270)
        {
            SsVariant v = { RBL_FACING_AXIS, false, cam != 0 };
            Image prev = { 0 };
            int worst = 0, worstAt = 0, steps = 0, total = 0;
            for (int k = -40; k <= 40; k++)          // elevation 70 .. 90 .. 70 through the zenith
            {
                double el = 90.0 - abs(k)*0.5, az = (k < 0)? (path? 90.0 : 0.0) : (path? 270.0 : 180.0);
                Vector3 L = ssToLight(az, el);
                RblLight light = ssLight(RBL_LIGHT_DIRECTIONAL, L);
                ssPass(&rig, &rig.maps[cam], &light, v, true, NULL, NULL);
                Image top = ssTop(&rig);
                int dark = 0;
                if (prev.data != NULL)
                {
                    int changed = 0;
                    for (int y = 0; y < SS_TOP; y++)
                        for (int x = 0; x < SS_TOP; x++)
                        {
                            bool a = rtPixel(prev, x, y).r < 140, b = rtPixel(top, x, y).r < 140;
                            changed += (a != b);
                        }
                    if (changed > worst) { worst = changed; worstAt = k; }
                    total += changed; steps++;
                    UnloadImage(prev);
                }
                for (int y = 0; y < SS_TOP; y++) for (int x = 0; x < SS_TOP; x++) dark += rtPixel(top, x, y).r < 140;
                RT_CHECK(cam || (dark > 30), "light-facing, elevation %.1f: the sprite casts %d pixels only", el, dark);
                prev = top;
            }
            UnloadImage(prev);
            // A rigid 1 x 2 card's shadow moving by 0.5 degrees changes a few pixel rows along its edges
            // (pixel 6/64 world units); a pop replaces most of its ~100..250 pixels at once
            printf("    %s casters, light over the %s: worst change %d floor pixels per 0.5-degree step (at %+.1f degrees from the zenith), mean %.1f\n",
                   cam? "camera-facing" : "light-facing ", path? "sides          " : "front and back", worst, worstAt*0.5, (double)total/steps);
            RT_CHECK(worst <= 24, "%s casters, light over the %s: the ground shadow jumps by %d pixels in one 0.5-degree step", cam? "camera-facing" : "light-facing", path? "sides" : "front and back", worst);
        }
    ssRigUnload(&rig);
}

// ---- the identity on every path, in any order ------------------------------------------------------
// The caster identity is the CPU's rbl__casterId for batched billboards and the instanced stage's
// rblCasterIdOf for instances: read back from the casters target, equal for 64 random pivots, sizes
// and origins (and never 0). A row of AXIS sprites cast through RblDrawInstanced in a shuffled
// order and received through a back-to-front sorted batch: none darkens itself.
static void test_shadows_caster_identity_is_the_same_on_every_path_and_in_any_order(void)
{
    unsigned int seed = 2604u;
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RT_CHECK(RblIsShadowMapValid(map) && (map.casters.id != 0), "shadow map with a casters target failed to load");
    RblLight sun = litDirectional((Vector3){ 0.0f, -1.0f, 0.0f }, 1.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1;
    Texture2D white = solidTexture(WHITE);
    Material m = LoadMaterialDefault();
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    Camera3D viewer = ssViewer();
    int mismatched = 0, zero = 0, checked = 0;
    for (int path = 0; path < (rtGlsl3()? 2 : 1); path++)
        for (int i = 0; i < 64; i++)
        {
            // A horizontal card covering the whole map (FIXED, facing up), seen from the sun above
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.position = (Vector3){ rtRandomRange(&seed, -1.0f, 1.0f), rtRandomRange(&seed, -1.0f, 1.0f), rtRandomRange(&seed, -1.0f, 1.0f) };
            b.size = (Vector2){ rtRandomRange(&seed, 40.0f, 50.0f), rtRandomRange(&seed, 40.0f, 50.0f) };
            b.origin = (Vector2){ b.size.x*rtRandomRange(&seed, 0.4f, 0.6f), b.size.y*rtRandomRange(&seed, 0.4f, 0.6f) };
            if (i == 0) { b.position = (Vector3){ 0.0f, 0.0f, 0.0f }; b.origin = (Vector2){ 0.0f, 0.0f }; b.size = (Vector2){ 40.0f, 40.0f }; }
            b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; b.up = (Vector3){ 0.0f, 0.0f, -1.0f };
            if (i == 0) b.position = (Vector3){ -20.0f, 0.0f, 20.0f };          // the pivot at a corner
            RT_CHECK(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 3.0f), "pass refused");
            if (path == 0) RblDrawBillboard(viewer, m, b);
            else
            {
                RblInstanceBuffer buf = RblLoadInstanceBuffer(1);
                RblInstance in;
                memset(&in, 0, sizeof(in));
                in.position = b.position; in.size = b.size; in.origin = b.origin;
                RblInstancedDesc d;
                memset(&d, 0, sizeof(d));
                d.facing = RBL_FACING_FIXED; d.axis = b.axis; d.up = b.up;
                RblDrawInstanced(&buf, viewer, m, d, &in, 1);
                RblUnloadInstanceBuffer(&buf);
            }
            RblEndShadowMap(&map);
            unsigned char *px = (unsigned char *)rlReadTexturePixels(map.casters.id, 64, 64, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
            unsigned int want = rbl__casterId(b.position, b.size, b.origin);
            unsigned int got = (px != NULL)? (unsigned int)px[(32*64 + 32)*4 + 2]*256u + px[(32*64 + 32)*4 + 3] : 0u;
            if (got != want) { mismatched++; if (mismatched < 4) printf("      %s: identity %u in the target, %u on the CPU\n", path? "instanced" : "batched", got, want); }
            zero += (got == 0u);
            checked++;
            RL_FREE(px);
        }
    RT_CHECK((mismatched == 0) && (zero == 0), "%d of %d identities differ from the CPU's (%d zero)", mismatched, checked, zero);
    printf("    %d casters (batched%s): the casters target holds the CPU's identity for each, none 0\n", checked, rtGlsl3()? " and instanced" : "");
    MemFree(m.maps);
    UnloadTexture(white);
    RblUnloadShadowMap(&map);

    // Instanced casters in a shuffled order, batched sorted receivers: no sprite darkens itself
    if (!rtGlsl3()) return;
    SsRig rig;
    RblLight probe = ssLight(RBL_LIGHT_DIRECTIONAL, ssToLight(0, 45));
    RT_CHECK(ssRigLoad(&rig, RblGetLightFeatures(&probe, 1), SS_MAP), "rig failed to load");
    Vector3 L = ssToLight(35, 30);
    RblLight light = ssLight(RBL_LIGHT_DIRECTIONAL, L);
    RblInstance row[9];
    int order[9];
    for (int i = 0; i < 9; i++)
    {
        memset(&row[i], 0, sizeof(row[i]));
        // Along the line across the light: no sprite's shadow reaches another
        float s = (i - 4)*0.45f;
        row[i].position = (Vector3){ s*L.z/sqrtf(L.x*L.x + L.z*L.z), 0.0f, -s*L.x/sqrtf(L.x*L.x + L.z*L.z) };
        row[i].size = (Vector2){ 0.3f, 1.8f - 0.05f*i }; row[i].origin = (Vector2){ 0.15f, 0.0f };
        order[i] = i;
    }
    for (int i = 8; i > 0; i--) { int j = (int)(rtRandom(&seed)%(unsigned int)(i + 1)), t = order[i]; order[i] = order[j]; order[j] = t; }
    RblInstance shuffled[9];
    for (int i = 0; i < 9; i++) shuffled[i] = row[order[i]];
    RblInstanceBuffer buf = RblLoadInstanceBuffer(9);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.facing = RBL_FACING_AXIS;
    Image img[2];
    for (int with = 0; with < 2; with++)
    {
        RblScene sc;
        memset(&sc, 0, sizeof(sc));
        sc.lights = &light; sc.lightCount = 1; sc.ambient = (Color){ SS_AMBIENT, SS_AMBIENT, SS_AMBIENT, 255 };
        RT_CHECK(RblBeginShadowMap(&rig.maps[0], &sc, 0, (Vector3){ 0.0f, 1.0f, 0.0f }, SS_RADIUS), "pass refused");
        if (with) RT_CHECK(RblDrawInstanced(&buf, viewer, rig.sprite, d, shuffled, 9) == 9, "instanced casters not drawn");
        RblEndShadowMap(&rig.maps[0]);
        sc.shadowMaps = &rig.maps[0]; sc.shadowMapCount = 1;
        RT_CHECK(RblSetScene(&sc), "scene rejected");
        RblBatch batch = RblLoadBatch(16);
        batch.sort = RBL_SORT_BACK_TO_FRONT;
        BeginTextureMode(rig.front);
        ClearBackground(BLANK);
        BeginMode3D(viewer);
        RblBeginBatch(&batch, viewer);
        for (int i = 0; i < 9; i++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.position = row[i].position; b.size = row[i].size; b.origin = row[i].origin; b.facing = RBL_FACING_AXIS;
            RblBatchAdd(&batch, rig.sprite, &b);
        }
        RblEndBatch(&batch);
        EndMode3D();
        EndTextureMode();
        RblUnloadBatch(&batch);
        img[with] = rtReadTarget(rig.front);
    }
    SsSelf s = ssSelfCompare(img[1], img[0]);
    RT_CHECK((s.covered > 150) && (s.darkened == 0), "instanced casters (shuffled) vs sorted batched receivers: %d of %d pixels darkened (worst %d/255)", s.darkened, s.covered, s.worst);
    printf("    9 AXIS sprites cast instanced in a shuffled order, received by a back-to-front batch: %d of %d pixels darkened\n", s.darkened, s.covered);
    if (s.darkened > 0) { rtSaveImage(img[1], "with"); rtSaveImage(img[0], "without"); }
    UnloadImage(img[0]); UnloadImage(img[1]);
    RblUnloadInstanceBuffer(&buf);
    ssRigUnload(&rig);
}

// ---- the option that turns identities off ------------------------------------------------------------
// RblShadowDesc.selfShadow: no casters target (casters.id 0; receivers sample the depth texture) and
// a billboard's own caster counts again: an AXIS sprite whose light-facing caster stands across its
// visible card darkens the half behind it. This is the mutation the sweep fails without.
static void test_shadows_self_shadow_option_drops_the_identities(void)
{
    SsRig rig;
    RblLight probe = ssLight(RBL_LIGHT_DIRECTIONAL, ssToLight(0, 45));
    RT_CHECK(ssRigLoad(&rig, RblGetLightFeatures(&probe, 1), SS_MAP), "rig failed to load");
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = SS_MAP; sd.selfShadow = true;
    RblShadowMap plain = RblLoadShadowMap(sd);
    RT_CHECK(RblIsShadowMapValid(plain) && (plain.casters.id == 0) && (plain.depth.id != 0), "selfShadow map: casters %u (expected none), depth %u", plain.casters.id, plain.depth.id);
    int darkened = 0, judged = 0, worst = 0;
    for (int az = 0; az < 360; az += 45)
    {
        Vector3 L = ssToLight(az, 45);
        RblLight light = ssLight(RBL_LIGHT_DIRECTIONAL, L);
        SsVariant v = { RBL_FACING_AXIS, false, false };
        ssPass(&rig, &plain, &light, v, false, NULL, NULL);
        Image without = ssFront(&rig, v);
        ssPass(&rig, &plain, &light, v, true, NULL, NULL);
        Image with = ssFront(&rig, v);
        SsSelf s = ssSelfCompare(with, without);
        darkened += (s.darkened > 0); judged++;
        if (s.worst > worst) worst = s.worst;
        UnloadImage(with); UnloadImage(without);
    }
    RT_CHECK(darkened >= judged/2, "selfShadow: the card darkens itself in %d of %d directions only (the option should bring self-shadowing back)", darkened, judged);
    printf("    selfShadow = true: no casters target; the light-facing AXIS sprite darkens itself in %d of %d directions (worst %d/255)\n", darkened, judged, worst);
    shClearScene();
    RblUnloadShadowMap(&plain);
    ssRigUnload(&rig);
}

// ---- deferred -----------------------------------------------------------------------------------
// The G-buffer keeps each pixel's caster identity (RT2 RGBA8 when it receives shadows): a sprite
// lit in deferred passes never darkens itself either, and matches the forward render within 2/255
// (outside the floor's contact band at its base, reported apart)
static void test_shadows_deferred_sprites_never_shadow_themselves_and_match_forward(void)
{
    SsRig rig;
    RblLight probe = ssLight(RBL_LIGHT_DIRECTIONAL, ssToLight(0, 45));
    RT_CHECK(ssRigLoad(&rig, RblGetLightFeatures(&probe, 1), SS_MAP), "rig failed to load");
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = SS_VIEW; gd.height = SS_VIEW; gd.shading.lightFeatures = RblGetLightFeatures(&probe, 1); gd.shading.shadowMaps = 1;
    RblGBuffer g = RblLoadGBuffer(gd);
    RblLitShaderDesc ld;
    memset(&ld, 0, sizeof(ld));
    ld.deferred = true; ld.material.normalEncoding = RBL_NORMAL_RGB;
    Shader geo = RblLoadLitShader(ld);
    RT_CHECK(RblIsGBufferValid(g) && RblIsLitShaderValid(geo), "G-buffer or geometry variant failed");
    RT_CHECK(RblGBufferBytesPerPixel(&g) == 12, "a G-buffer receiving shadows stores %d bytes per pixel (expected 12: RT2 RGBA8 with the caster identity)", RblGBufferBytesPerPixel(&g));
    Material dm = rig.sprite;
    dm.shader = geo;
    Camera3D viewer = ssViewer();
    int worstDiff = 0, worstContact = 0, contactPixels = 0, selfCases = 0, cases = 0;
    for (int az = 0; az < 360; az += 45)
        for (int el = 15; el <= 75; el += 30)
            for (int f = 0; f < 3; f++)
                for (int cam = 0; cam < 2; cam++)
                {
                    Vector3 L = ssToLight(az, el);
                    RblLight light = ssLight(RBL_LIGHT_DIRECTIONAL, L);
                    SsVariant v = { ssFacings[f], false, cam != 0 };
                    Image img[2];
                    for (int with = 0; with < 2; with++)
                    {
                        ssPass(&rig, &rig.maps[cam], &light, v, with != 0, NULL, NULL);
                        if (RblBeginGBuffer(&g, viewer))
                        {
                            RblDrawBillboard(viewer, dm, ssSprite(v));
                            RblEndGBuffer(&g);
                            RblDrawDeferredLights(&g);
                        }
                        BeginTextureMode(rig.front);
                        ClearBackground(BLANK);
                        RblResolveGBuffer(&g);
                        EndTextureMode();
                        img[with] = rtReadTarget(rig.front);
                    }
                    Image fwd = ssFront(&rig, v);          // forward, the sprite in the pass (the last pass)
                    ssNoMap(&light);
                    Image bare = ssFront(&rig, v);         // forward without a map: where the floor's contact acts
                    SsSelf s = ssSelfCompare(img[1], img[0]);
                    selfCases += (s.darkened > 0);
                    for (int y = 0; y < SS_VIEW; y++)
                        for (int x = 0; x < SS_VIEW; x++)
                        {
                            Color a = rtPixel(img[1], x, y), b = rtPixel(fwd, x, y), c = rtPixel(bare, x, y);
                            if (b.a < 255) continue;
                            int dd = abs((int)a.r - b.r);
                            if (abs((int)a.g - b.g) > dd) dd = abs((int)a.g - b.g);
                            if (abs((int)a.b - b.b) > dd) dd = abs((int)a.b - b.b);
                            // The floor's PCF footprint at the sprite's base (contact): each path takes the
                            // card's plane its own way (screen derivatives, depth neighbours); reported apart
                            bool contact = (abs((int)b.r - c.r) > 2) || (abs((int)a.r - c.r) > 2);
                            if (contact) { if (dd > worstContact) worstContact = dd; contactPixels++; }
                            else if (dd > worstDiff) worstDiff = dd;
                        }
                    cases++;
                    UnloadImage(img[0]); UnloadImage(img[1]); UnloadImage(fwd); UnloadImage(bare);
                }
    RT_CHECK(selfCases == 0, "deferred: the sprite darkens itself in %d of %d cases", selfCases, cases);
    RT_CHECK(worstDiff <= 2, "deferred vs forward: worst %d/255 on the sprite outside the floor's contact", worstDiff);
    printf("    deferred, %d cases (camera-plane, camera-position, axis; both caster modes): %d self-darken, worst %d/255 against forward (%d contact pixels, where the floor's PCF reaches the base: worst %d/255)\n",
           cases, selfCases, worstDiff, contactPixels, worstContact);
    shClearScene();
    RblUnloadLitShader(&geo);
    RblUnloadGBuffer(&g);
    ssRigUnload(&rig);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_SELF_SHADOW_TESTS \
    RT_TEST(test_shadows_sprites_never_shadow_themselves_in_a_sweep_of_every_light_direction), \
    RT_TEST(test_shadows_sprite_receives_a_crates_shadow_and_never_its_own_in_the_users_scene), \
    RT_TEST(test_shadows_sprite_receives_a_crates_shadow_under_a_point_light), \
    RT_TEST(test_shadows_light_over_an_axis_sprite_moves_its_shadow_continuously), \
    RT_TEST(test_shadows_caster_identity_is_the_same_on_every_path_and_in_any_order), \
    RT_TEST(test_shadows_self_shadow_option_drops_the_identities), \
    RT_TEST_GLSL3(test_shadows_deferred_sprites_never_shadow_themselves_and_match_forward)
