// Shadow specification (GPU, headless). A white floor (z = 0, facing +Z) is seen straight down by an
// orthographic camera, so every pixel maps to a known floor point; casters are drawn only into the
// shadow map, so the whole footprint is visible. Checked: a sprite's transparent hole lets light
// through on every billboard path; an opaque card darkens exactly its analytic footprint (directional
// and spot) within a texel; a floor lit at up to 80 degrees incidence shows no acne; a card standing
// on the floor casts from its base (no peter-panning beyond a texel); an axis-locked billboard under a
// light straight above still casts; the AXIS tilt is the same on the CPU and the GPU; forward and
// deferred agree; bad input is refused and changes nothing; hard cases stay finite.
// Included by test_gpu_main.c after test_deferred.c.

#define SH_TARGET 128
#define SH_VIEW 8.0f            // world units the top-down camera sees across (pixel = 1/16)
#define SH_MAP 512
#define SH_FOCUS 4.0f           // focus sphere radius around the origin: texel = 8/511 world units

typedef struct ShSetup {
    RblLight lights[2];
    int count;
    Color ambient;
    RblShadowDesc shadow;
    Vector3 focus;
    float radius;
    Camera3D camera;            // the image's camera (top-down orthographic)
    Camera3D viewer;            // camera the billboards face in the shadow pass
    int filter;                 // desc.shadowFilter
    int brdf;
    bool noShadow;              // reference render: no shadow pass, no map given
} ShSetup;

typedef void (*ShCasters)(Material m, Camera3D viewer, void *ctx);

static Camera3D shTopDown(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 0.0f, 10.0f }; c.target = (Vector3){ 0.0f, 0.0f, 0.0f }; c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = SH_VIEW; c.projection = CAMERA_ORTHOGRAPHIC;
    return c;
}

static ShSetup shSetup(Vector3 direction)
{
    ShSetup s;
    memset(&s, 0, sizeof(s));
    s.lights[0] = litDirectional(direction, 1.0f);
    s.count = 1;
    s.ambient = (Color){ 40, 40, 40, 255 };
    s.shadow.size = SH_MAP;
    s.radius = SH_FOCUS;
    s.camera = shTopDown();
    s.viewer = litCamera((Vector3){ 0.0f, -8.0f, 3.0f }, (Vector3){ 0.0f, 0.0f, 0.5f });
    s.viewer.up = (Vector3){ 0.0f, 0.0f, 1.0f };
    return s;
}

// An empty scene (no lights, no maps), set before a test unloads the maps its scene listed
static void shClearScene(void)
{
    RblScene none;
    memset(&none, 0, sizeof(none));
    RT_CHECK(RblSetScene(&none), "empty scene rejected");
}

// Floor point seen at pixel (x, y) of the top-down image (top row first)
static Vector2 shFloorAt(int x, int y)
{
    float p = SH_VIEW/SH_TARGET;
    return (Vector2){ (x + 0.5f)*p - SH_VIEW*0.5f, SH_VIEW*0.5f - (y + 0.5f)*p };
}

// Renders the floor lit by s's lights with the casters drawn into the shadow map (forward, or deferred).
// The scene (lights, ambient, and the map once rendered) is set after the shadow pass, as receivers need.
static Image shRender(const ShSetup *s, ShCasters casters, void *ctx, Texture2D casterTexture, bool deferred)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = s->count;
    desc.shading.lightFeatures = RblGetLightFeatures(s->lights, s->count);
    desc.shading.brdf = s->brdf;
    desc.shading.shadowMaps = 1;
    desc.shading.shadowFilter = s->filter;
    Shader lit = RblLoadLitShader(desc);
    RblShadowMap map = RblLoadShadowMap(s->shadow);
    RT_CHECK(RblIsLitShaderValid(lit) && RblIsShadowMapValid(map), "receiver or shadow map failed to load");
    Material cm = LoadMaterialDefault();
    cm.shader = lit;                        // the colour pass's material: the shadow pass swaps the caster in
    cm.maps[MATERIAL_MAP_ALBEDO].texture = casterTexture;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = s->lights;
    scene.lightCount = s->count;
    scene.ambient = s->ambient;
    if (!s->noShadow)
    {
        RT_CHECK(RblBeginShadowMap(&map, &scene, 0, s->focus, s->radius), "shadow pass refused");
        if (casters != NULL) casters(cm, s->viewer, ctx);
        RblEndShadowMap(&map);
        scene.shadowMaps = &map;            // received once rendered: the scene is set after the pass
        scene.shadowMapCount = 1;
    }
    Texture2D white = solidTexture(WHITE);
    Material floor = LoadMaterialDefault();
    floor.maps[MATERIAL_MAP_ALBEDO].texture = white;
    RenderTexture2D rt = LoadRenderTexture(SH_TARGET, SH_TARGET);
    if (!deferred)
    {
        RT_CHECK(RblSetScene(&scene), "scene (lights, shadow map) rejected");
        floor.shader = lit;
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        BeginMode3D(s->camera);
        RblDrawBillboard(s->camera, floor, litPlane());
        EndMode3D();
        EndTextureMode();
    }
    else
    {
        RblGBufferDesc gdesc;
        memset(&gdesc, 0, sizeof(gdesc));
        gdesc.width = SH_TARGET; gdesc.height = SH_TARGET;
        gdesc.shading = desc.shading;
        RblGBuffer g = RblLoadGBuffer(gdesc);
        desc.deferred = true;
        Shader geo = RblLoadLitShader(desc);
        RT_CHECK(RblIsGBufferValid(g) && RblIsLitShaderValid(geo), "G-buffer or geometry variant failed");
        RT_CHECK(RblSetScene(&scene), "scene (lights, G-buffer shadow map) rejected");
        floor.shader = geo;
        if (RblBeginGBuffer(&g, s->camera))
        {
            RblDrawBillboard(s->camera, floor, litPlane());
            RblEndGBuffer(&g);
            RT_CHECK(RblDrawDeferredLights(&g), "deferred lights rejected");
        }
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        RblResolveGBuffer(&g);
        EndTextureMode();
        RblUnloadLitShader(&geo);
        RblUnloadGBuffer(&g);
    }
    Image img = rtReadTarget(rt);
    shClearScene();                         // the scene no longer lists the map unloaded below
    UnloadRenderTexture(rt);
    UnloadTexture(white);
    MemFree(floor.maps);
    MemFree(cm.maps);
    RblUnloadShadowMap(&map);
    RblUnloadLitShader(&lit);
    return img;
}

// ---- casters ------------------------------------------------------------------------------------
typedef struct ShCard { Vector3 centre; float size; int path; } ShCard;      // path: 0 immediate, 1 batched, 2 instanced

// A horizontal card (FIXED facing +Z) of side `size` centred at `centre`, on one of the three paths
static void shCardCasters(Material m, Camera3D viewer, void *ctx)
{
    const ShCard *c = (const ShCard *)ctx;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = c->centre; b.size = (Vector2){ c->size, c->size }; b.origin = (Vector2){ c->size*0.5f, c->size*0.5f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    if (c->path == 0) RblDrawBillboard(viewer, m, b);
    else if (c->path == 1)
    {
        RblBatch batch = RblLoadBatch(4);
        RblBeginBatch(&batch, viewer);
        RblBatchAdd(&batch, m, &b);
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
    }
    else
    {
        RblInstanceBuffer buf = RblLoadInstanceBuffer(4);
        RblInstance in;
        memset(&in, 0, sizeof(in));
        in.position = b.position; in.size = b.size; in.origin = b.origin;
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = RBL_FACING_FIXED; d.axis = b.axis; d.up = b.up;
        RT_CHECK(RblDrawInstanced(&buf, viewer, m, d, &in, 1) == 1, "instanced caster not drawn");
        RblUnloadInstanceBuffer(&buf);
    }
}

static void shFloorCaster(Material m, Camera3D viewer, void *ctx)
{
    (void)ctx;
    RblDrawBillboard(viewer, m, litPlane());
}

// Lit and shadowed floor values (sRGB bytes) and the threshold halfway between them
static int shThreshold(Image lit, Image dark)
{
    return (rtPixel(lit, SH_TARGET/2, SH_TARGET/2).r + rtPixel(dark, SH_TARGET/2, SH_TARGET/2).r)/2;
}

// Signed distance from p to the boundary of the axis-aligned square [lo, hi] (negative inside)
static float shSquareDistance(Vector2 p, Vector2 lo, Vector2 hi)
{
    float dx = fmaxf(lo.x - p.x, p.x - hi.x), dy = fmaxf(lo.y - p.y, p.y - hi.y);
    if ((dx <= 0.0f) && (dy <= 0.0f)) return fmaxf(dx, dy);
    return sqrtf(fmaxf(dx, 0.0f)*fmaxf(dx, 0.0f) + fmaxf(dy, 0.0f)*fmaxf(dy, 0.0f));
}

// ---- footprints ---------------------------------------------------------------------------------
// A card at height 1 under a tilted directional light: the shadow is the card shifted by
// height*(D.x, D.y)/-D.z; every pixel farther than one texel from that square's edge is classified right
static void test_shadows_opaque_card_darkens_its_analytic_footprint_within_a_texel(void)
{
    Vector3 dir = { 0.5f, 0.3f, -1.0f };
    ShSetup s = shSetup(dir);
    Texture2D opaque = solidTexture(WHITE);
    ShSetup ref = s; ref.noShadow = true;
    Image lit = shRender(&ref, NULL, NULL, opaque, false);
    float texel = 2.0f*SH_FOCUS/(SH_MAP - 1);
    for (int spot = 0; spot < 2; spot++)
    {
        ShSetup t = s;
        ShCard card = { { 0.0f, 0.0f, 1.0f }, 2.0f, 0 };
        Vector2 lo, hi;
        if (!spot) { lo = (Vector2){ -1.0f + 0.5f, -1.0f + 0.3f }; hi = (Vector2){ 1.0f + 0.5f, 1.0f + 0.3f }; }
        else
        {
            // Spot straight down from height 4: the card at height 1 projects scaled by 4/(4 - 1) about the light's foot
            t.lights[0] = litSpot((Vector3){ 0.3f, -0.2f, 4.0f }, (Vector3){ 0.0f, 0.0f, -1.0f }, 50.0f, 60.0f, 16.0f);
            t.lights[0].range = 0.0f;
            t.focus = (Vector3){ 0.0f, 0.0f, 0.0f }; t.radius = 4.0f;
            float k = 4.0f/3.0f;
            lo = (Vector2){ 0.3f + (-1.0f - 0.3f)*k, -0.2f + (-1.0f + 0.2f)*k };
            hi = (Vector2){ 0.3f + (1.0f - 0.3f)*k, -0.2f + (1.0f + 0.2f)*k };
        }
        ShSetup tref = t; tref.noShadow = true;
        Image base = spot? shRender(&tref, NULL, NULL, opaque, false) : lit;
        Image img = shRender(&t, shCardCasters, &card, opaque, false);
        int wrong = 0, inside = 0, worstWrongPx = -1;
        float worstDist = 0.0f;
        for (int y = 0; y < SH_TARGET; y++)
            for (int x = 0; x < SH_TARGET; x++)
            {
                Vector2 p = shFloorAt(x, y);
                float d = shSquareDistance(p, lo, hi);
                // A pixel is dark when it is below half of its own unshadowed value (spot light varies)
                int b = rtPixel(base, x, y).r, v = rtPixel(img, x, y).r, ambient = 40;     // white floor under ambient 40 alone
                if (b - 24 < ambient) continue;                                  // not lit enough to tell
                bool dark = v < (b + 40)/2;
                if (d < 0.0f) inside++;
                if ((fabsf(d) > texel) && (dark != (d < 0.0f))) { wrong++; if (fabsf(d) > worstDist) { worstDist = fabsf(d); worstWrongPx = y*SH_TARGET + x; } }
            }
        float texelHere = spot? (float)(2.0*tan(60.0*PI/180.0)/SH_MAP*4.0) : texel;
        RT_CHECK(inside > 500, "%s: footprint too small to judge (%d pixels)", spot? "spot" : "directional", inside);
        RT_CHECK(wrong == 0, "%s: %d pixels misclassified more than a texel (%.4f) from the analytic edge (worst %.4f at pixel %d)",
                 spot? "spot" : "directional", wrong, texel, worstDist, worstWrongPx);
        printf("    %s: %d footprint pixels, %d misclassified beyond one texel of the analytic edge (texel %.4f world units)\n",
               spot? "spot (perspective)" : "directional (orthographic)", inside, wrong, texelHere);
        if (wrong > 0) rtSaveImage(img, spot? "spot" : "directional");
        UnloadImage(img);
        if (spot) UnloadImage(base);
    }
    UnloadImage(lit);
    UnloadTexture(opaque);
}

// A sprite with a transparent hole casts a shadow with the hole in it, on all three billboard paths
static void test_shadows_transparent_hole_in_a_sprite_lets_light_through_on_every_path(void)
{
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    s.lights[0].direction = (Vector3){ 0.4f, 0.0f, -1.0f };
    Image img = GenImageColor(64, 64, WHITE);
    ImageDrawCircle(&img, 32, 32, 14, BLANK);                // hole: radius 14/64 of the card = 0.44 world units
    Texture2D holed = LoadTextureFromImage(img);
    UnloadImage(img);
    for (int path = 0; path < (rtGlsl3()? 3 : 2); path++)     // instanced: GLSL 3 contexts
    {
        ShCard card = { { 0.0f, 0.0f, 1.0f }, 2.0f, path };
        Image out = shRender(&s, shCardCasters, &card, holed, false);
        // Footprint centre: (0, 0) + 1*(0.4, 0)
        int cx = (int)((0.4f + SH_VIEW*0.5f)/SH_VIEW*SH_TARGET), cy = SH_TARGET/2;
        int hole = rtPixel(out, cx, cy).r, ring = rtPixel(out, cx + 11, cy).r, outside = rtPixel(out, cx + 24, cy).r;
        RT_CHECK(hole > outside - 3 && ring < outside - 40, "path %d: hole %d, ring %d, unshadowed %d: the hole is not in the shadow", path, hole, ring, outside);
        printf("    path %d: hole centre %d, opaque ring %d, unshadowed floor %d\n", path, hole, ring, outside);
        if (rtFailuresInCurrentTest() > 0) rtSaveImage(out, "hole");
        UnloadImage(out);
    }
    UnloadTexture(holed);
}

// ---- bias -----------------------------------------------------------------------------------------
// The floor casts into its own map; lit at 0..80 degrees incidence it must look exactly unshadowed
static void test_shadows_no_acne_on_a_floor_lit_at_up_to_80_degrees(void)
{
    Texture2D white = solidTexture(WHITE);
    for (int f = 1; f <= 3; f += 2)
    for (int a = 0; a <= 80; a += 20)
    {
        float t = a*(PI/180.0f);
        ShSetup s = shSetup((Vector3){ sinf(t)*0.8f, sinf(t)*0.6f, -cosf(t) });
        s.filter = f;
        ShSetup ref = s; ref.noShadow = true;
        Image base = shRender(&ref, NULL, NULL, white, false), img = shRender(&s, shFloorCaster, NULL, white, false);
        for (int deferred = 0; deferred < (rtGlsl3()? 2 : 1); deferred++)
        {
            Image cmp = deferred? shRender(&s, shFloorCaster, NULL, white, true) : img;
            int worst = 0, acne = 0;
            for (int y = 0; y < SH_TARGET; y++)
                for (int x = 0; x < SH_TARGET; x++)
                {
                    int d = abs(rtPixel(cmp, x, y).r - rtPixel(base, x, y).r);
                    if (d > worst) worst = d;
                    if (d > 2) acne++;
                }
            RT_CHECK(acne == 0, "%s filter %d at %d degrees: %d pixels darker than unshadowed (worst %d/255)", deferred? "deferred" : "forward", f, a, acne, worst);
            if (a == 80) printf("    %s, filter %d, 80 degrees incidence: worst %d/255 against the unshadowed floor\n", deferred? "deferred" : "forward", f, worst);
            if (acne > 0) rtSaveImage(cmp, "acne");
            if (deferred) UnloadImage(cmp);
        }
        UnloadImage(base); UnloadImage(img);
    }
    UnloadTexture(white);
}

// A card standing on the floor (normal -X, base on the floor along y) under light at 45 and 60 degrees:
// the shadow starts at the base; the lit gap between base and shadow is at most one texel
typedef struct ShWall { float height; } ShWall;
static void shWallCaster(Material m, Camera3D viewer, void *ctx)
{
    const ShWall *w = (const ShWall *)ctx;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ 0.0f, 0.0f, 0.0f }; b.size = (Vector2){ 3.0f, w->height }; b.origin = (Vector2){ 1.5f, 0.0f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ -1.0f, 0.0f, 0.0f }; b.up = (Vector3){ 0.0f, 0.0f, 1.0f };
    RblDrawBillboard(viewer, m, b);
    RblDrawBillboard(viewer, m, litPlane());        // the floor casts too, as in a scene
}

static void test_shadows_standing_card_casts_from_its_base_without_peter_panning(void)
{
    Texture2D white = solidTexture(WHITE);
    ShWall wall = { 1.0f };
    float texel = 2.0f*SH_FOCUS/(SH_MAP - 1), pixel = SH_VIEW/SH_TARGET;
    for (int a = 30; a <= 75; a += 15)
    {
        float t = a*(PI/180.0f);
        ShSetup s = shSetup((Vector3){ sinf(t), 0.0f, -cosf(t) });     // light travels +X: shadow on the +X side
        ShSetup ref = s; ref.noShadow = true;
        Image base = shRender(&ref, NULL, NULL, white, false), img = shRender(&s, shWallCaster, &wall, white, false);
        int row = SH_TARGET/2, thr = shThreshold(base, img);
        // Gap: the first dark pixel past the base (x = 0), seen by a camera zoomed to half a texel per pixel
        ShSetup zoom = s;
        float zpixel = 1.0f/SH_TARGET;
        zoom.camera.fovy = 1.0f;
        zoom.camera.position.x = zoom.camera.target.x = 0.5f;           // sees x in [0, 1]
        Image near = shRender(&zoom, shWallCaster, &wall, white, false);
        float gap = -1.0f;
        for (int x = 0; x < SH_TARGET; x++)
            if (rtPixel(near, x, row).r < thr) { gap = x*zpixel; break; }   // pixel x spans [x, x + 1)*zpixel
        if (rtFailuresInCurrentTest() > 0) rtSaveImage(near, "wall-zoom");
        UnloadImage(near);
        float expectedEnd = wall.height*tanf(t);
        int endX = (int)((expectedEnd + SH_VIEW*0.5f)/pixel);
        bool shadowEnds = (rtPixel(img, endX - 2, row).r < thr) && (rtPixel(img, endX + 2, row).r >= thr);
        RT_CHECK(gap >= 0.0f && gap <= texel, "%d degrees: gap between the base and the shadow %.4f (texel %.4f)", a, gap, texel);
        RT_CHECK(shadowEnds, "%d degrees: the shadow does not end at height*tan = %.3f", a, expectedEnd);
        printf("    %d degrees: shadow starts within %.4f of the base (texel %.4f, measured with %.4f pixels), ends at %.3f = height*tan(incidence)\n", a, gap, texel, zpixel, expectedEnd);
        if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, "wall");
        UnloadImage(base); UnloadImage(img);
    }
    UnloadTexture(white);
}

// ---- axis-locked billboards --------------------------------------------------------------------
typedef struct ShTree { int path; } ShTree;
static void shTreeCaster(Material m, Camera3D viewer, void *ctx)
{
    const ShTree *t = (const ShTree *)ctx;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ 0.0f, 0.0f, 0.0f }; b.size = (Vector2){ 1.0f, 2.0f }; b.origin = (Vector2){ 0.5f, 0.0f };
    b.facing = RBL_FACING_AXIS; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    if (t->path == 0) { RblDrawBillboard(viewer, m, b); return; }
    RblInstanceBuffer buf = RblLoadInstanceBuffer(2);
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.position = b.position; in.size = b.size; in.origin = b.origin;
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.facing = RBL_FACING_AXIS; d.axis = b.axis;
    RblDrawInstanced(&buf, viewer, m, d, &in, 1);
    RblUnloadInstanceBuffer(&buf);
}

static int shDarkPixels(Image img, int thr)
{
    int n = 0;
    for (int y = 0; y < SH_TARGET; y++) for (int x = 0; x < SH_TARGET; x++) if (rtPixel(img, x, y).r < thr) n++;
    return n;
}

// Light straight down the locked axis: the upright card is edge-on to it, yet a shadow falls (the
// shadow pass tilts it to the minimum angle); with the tilt disabled it would cast nothing
static void test_shadows_axis_locked_billboard_casts_under_a_light_straight_above(void)
{
    Texture2D white = solidTexture(WHITE);
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    ShSetup ref = s; ref.noShadow = true;
    Image base = shRender(&ref, NULL, NULL, white, false);
    float pixel = SH_VIEW/SH_TARGET;
    double expected = 1.0*2.0*sin(30.0*PI/180.0)/(pixel*pixel);      // width x height x sin(minimum angle), in pixels
    for (int path = 0; path < (rtGlsl3()? 2 : 1); path++)     // instanced: GLSL 3 contexts
    {
        ShTree tree = { path };
        Image img = shRender(&s, shTreeCaster, &tree, white, false);
        int dark = shDarkPixels(img, shThreshold(base, img));
        RT_CHECK(fabs(dark - expected) < 0.15*expected, "%s: %d shadowed pixels, expected about %.0f (1 x 2 card seen at 30 degrees)", path? "instanced" : "immediate", dark, expected);
        printf("    %s: light along the axis, %d shadowed pixels (1 x 2 card at the default 30-degree minimum: %.0f)\n", path? "instanced" : "immediate", dark, expected);
        if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, "axis");
        UnloadImage(img);
    }
    ShSetup never = s;
    never.shadow.minCastAngle = -1.0f;
    ShTree tree = { 0 };
    Image img = shRender(&never, shTreeCaster, &tree, white, false);
    int dark = shDarkPixels(img, shThreshold(base, base) - 20);
    RT_CHECK(dark < expected*0.1, "tilt disabled: %d shadowed pixels (edge-on card should cast almost nothing)", dark);
    printf("    tilt disabled (minCastAngle < 0): %d shadowed pixels\n", dark);
    UnloadImage(img); UnloadImage(base);
    UnloadTexture(white);
}

// The AXIS tilt of a shadow pass, CPU and GPU: the light sees the quad at >= the minimum angle, the
// frame stays orthonormal, the quad keeps its pivot, and the instanced stage emits the same vertices
static void test_shadows_axis_tilt_is_the_same_on_cpu_and_gpu(void)
{
    Camera3D cam = litCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    rbl__Cast cast;                 // what a shadow pass gives the CPU path (the header's internal frame input)
    memset(&cast, 0, sizeof(cast));
    cast.minSin = sinf(30.0f*PI/180.0f);
    unsigned int seed = 4242u;
    double worstAngle = 90.0, worstOrtho = 0.0;
    for (int i = 0; i < 200; i++)
    {
        Vector3 L = { rtRandomRange(&seed, -0.3f, 0.3f), 1.0f, rtRandomRange(&seed, -0.3f, 0.3f) };   // near the +Y axis
        float l = sqrtf(L.x*L.x + L.y*L.y + L.z*L.z);
        cast.light = (Vector4){ L.x/l, L.y/l, L.z/l, 0.0f };
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.position = (Vector3){ rtRandomRange(&seed, -5, 5), 0.0f, rtRandomRange(&seed, -5, 5) };
        b.size = (Vector2){ 1.0f, 2.0f }; b.origin = (Vector2){ 0.5f, 0.0f }; b.facing = RBL_FACING_AXIS;
        RblVertex q[4];
        rbl__FrameCache cache;
        cache.facing = -1;
        RT_CHECK(rbl__billboardVertices(&view, &cast, &cache, 16, 16, &b, q), "tilted billboard skipped");
        Vector3 n = { q[0].normal[0], q[0].normal[1], q[0].normal[2] }, t = { q[0].tangent[0], q[0].tangent[1], q[0].tangent[2] };
        Vector3 e1 = { q[1].position[0] - q[0].position[0], q[1].position[1] - q[0].position[1], q[1].position[2] - q[0].position[2] };
        Vector3 e2 = { q[3].position[0] - q[0].position[0], q[3].position[1] - q[0].position[1], q[3].position[2] - q[0].position[2] };
        double seen = asin(fmin(1.0, fabs(n.x*cast.light.x + n.y*cast.light.y + n.z*cast.light.z)))*180.0/PI;
        if (seen < worstAngle) worstAngle = seen;
        worstOrtho = fmax(worstOrtho, fabs(n.x*t.x + n.y*t.y + n.z*t.z));
        worstOrtho = fmax(worstOrtho, fabs(e1.x*e2.x + e1.y*e2.y + e1.z*e2.z)/(Vector3Length(e1)*Vector3Length(e2)));
        worstOrtho = fmax(worstOrtho, fabs(Vector3Length(e2) - 2.0f)/2.0f);
        // The quad turns about the line across it at height h (in double, from the documented rule):
        // the bottom edge under a low light, mid-height as the light nears the axis (smoothstep of
        // |l.a| from cos 30 to 1); points on that line keep their place, every corner its distance
        // to it and its offset along it (the pivot line r)
        double la = fabs((double)cast.light.y), g = fmin(fmax((la - sqrt(3.0)/2.0)/(1.0 - sqrt(3.0)/2.0), 0.0), 1.0);
        double h = 1.0*g*g*(3.0 - 2.0*g);               // half the 2-unit height at full weight
        RblVertex u[4];
        rbl__Cast none = cast;
        none.minSin = 0.0f;
        cache.facing = -1;
        rbl__billboardVertices(&view, &none, &cache, 16, 16, &b, u);      // the untilted quad
        double hinge[3] = { b.position.x, b.position.y + h, b.position.z }, r[3] = { e1.x, e1.y, e1.z }, rl = sqrt(r[0]*r[0] + r[1]*r[1] + r[2]*r[2]);
        for (int c = 0; c < 4; c++)
        {
            double dt[3], du[3];
            for (int k = 0; k < 3; k++) { dt[k] = q[c].position[k] - hinge[k]; du[k] = u[c].position[k] - hinge[k]; }
            worstOrtho = fmax(worstOrtho, fabs(sqrt(dt[0]*dt[0] + dt[1]*dt[1] + dt[2]*dt[2]) - sqrt(du[0]*du[0] + du[1]*du[1] + du[2]*du[2])));
            worstOrtho = fmax(worstOrtho, fabs((dt[0] - du[0])*r[0] + (dt[1] - du[1])*r[1] + (dt[2] - du[2])*r[2])/rl);
        }
    }
    RT_CHECK(worstAngle >= 29.9, "the light sees a tilted quad at %.3f degrees (minimum 30)", worstAngle);
    RT_CHECK(worstOrtho < 1e-5, "tilted frame not orthonormal / not turning about its hinge line (%.3g)", worstOrtho);
    // GPU: the instanced stage with the same shadow-pass frame
    TfGl gl;
    if (!tfLoad(&gl)) { RT_CHECK(false, "transform feedback entry points missing"); return; }
    GLu prog = tfProgram(&gl);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(64);
    RblInstance in[64];
    for (int i = 0; i < 64; i++) in[i] = randomInstance(&seed);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.facing = RBL_FACING_AXIS;
    double worst = 0.0;
    for (int lightKind = 0; lightKind < 4; lightKind++)
    {
        // camera-facing casters, then light-facing ones (their flags in the facing code)
        cast.light = (lightKind & 1)? (Vector4){ 2.0f, 30.0f, -1.0f, 1.0f } : (Vector4){ 0.1f, 0.99f, 0.1f, 0.0f };
        cast.faceLight = (lightKind >= 2);
        tfLight = cast.light; tfMinCastSin = cast.minSin; tfFacingFlags = cast.faceLight? 8 : 0;
        float *gpu = tfCapture(&gl, prog, &buf, cam, d, 256, 128, in, 64);
        tfLight = (Vector4){ 0 }; tfMinCastSin = 0.0f; tfFacingFlags = 0;
        const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
        for (int i = 0; i < 64; i++)
        {
            RblBillboard b = billboardOf(&in[i], d);
            RblVertex q[4];
            rbl__FrameCache cache;
            cache.facing = -1;
            rbl__billboardVertices(&view, &cast, &cache, 256, 128, &b, q);
            double scale = 1.0 + fabs(b.position.x) + fabs(b.position.y) + fabs(b.position.z) + fabs(b.size.x) + fabs(b.size.y) + fabs(b.origin.x) + fabs(b.origin.y);
            for (int v = 0; v < 6; v++)
            {
                const float *g = gpu + ((size_t)i*6 + v)*TF_FLOATS;
                const RblVertex *c = &q[cornerOf[v]];
                for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(g[k] - c->position[k])/scale);
                for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(g[5 + k] - c->normal[k]));
            }
        }
        free(gpu);
    }
    RT_CHECK(worst < 2e-5, "instanced vs cpu in a shadow pass: worst difference %.3g", worst);
    printf("    tilt: light sees the quad at >= %.2f degrees (minimum 30), frame error %.1e; instanced vs cpu %.1e\n", worstAngle, worstOrtho, worst);
    gl.DeleteProgram(prog);
    RblUnloadInstanceBuffer(&buf);
}

// ---- forward and deferred ---------------------------------------------------------------------
// The same shadowed floor (card + floor casters, directional and spot maps) forward and deferred, at a
// map texel about the size of a pixel (128 texels over the 8-unit focus). Also reported, not asserted:
// the same at 4 texels per pixel, where the whole PCF edge is a quarter pixel wide and the G-buffer's
// depth (raylib's 0.05..4000 range) moves it by ~1e-4 units: a few /255 on the edge pixels
static void test_shadows_forward_and_deferred_agree_within_2_of_255(void)
{
    Texture2D white = solidTexture(WHITE);
    Image img = GenImageColor(64, 64, WHITE);
    ImageDrawCircle(&img, 32, 32, 14, BLANK);
    Texture2D holed = LoadTextureFromImage(img);
    UnloadImage(img);
    for (int magnified = 0; magnified < 2; magnified++)
    for (int brdf = RBL_BRDF_LAMBERT; brdf <= RBL_BRDF_GGX; brdf++)
    for (int spot = 0; spot < 2; spot++)
    {
        ShSetup s = shSetup((Vector3){ 0.5f, 0.3f, -1.0f });
        s.brdf = brdf;
        s.shadow.size = magnified? SH_MAP : 128;
        if (spot)
        {
            s.lights[0] = litSpot((Vector3){ 0.3f, -0.2f, 4.0f }, (Vector3){ 0.1f, 0.0f, -1.0f }, 40.0f, 60.0f, 16.0f);
            s.lights[0].range = 9.0f;
        }
        ShCard card = { { 0.0f, 0.0f, 1.0f }, 2.0f, 1 };
        Image fwd = shRender(&s, shCardCasters, &card, holed, false), def = shRender(&s, shCardCasters, &card, holed, true);
        DefDiff d = defCompare(fwd, def);
        RT_CHECK((magnified || d.worst <= 2) && d.coverage == 0 && d.covered > 1000, "brdf %d %s: forward vs deferred worst %d/255 (%d over 2), coverage differs in %d",
                 brdf, spot? "spot" : "directional", d.worst, d.over2, d.coverage);
        printf("    %s brdf %d, %s: %d pixels, worst %d/255 (%d pixels over 2), mean %.3f/255\n", magnified? "4 texels/pixel:" : "1 texel/pixel: ",
               brdf, spot? "spot" : "directional", d.covered, d.worst, d.over2, d.mean);
        if (!magnified && (d.worst > 2)) { rtSaveImage(fwd, "forward"); rtSaveImage(def, "deferred"); }
        UnloadImage(fwd); UnloadImage(def);
    }
    UnloadTexture(white); UnloadTexture(holed);
}

// ---- bad input and hard cases -------------------------------------------------------------------
// Floor colour at the centre of a small top-down render drawn with m under the current scene
static Color shProbe(Material m)
{
    Camera3D cam = shTopDown();
    RenderTexture2D rt = LoadRenderTexture(8, 8);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(cam);
    RblDrawBillboard(cam, m, litPlane());
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    Color c = rtPixel(img, 4, 4);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    return c;
}

static bool shSameColor(Color a, Color b) { return (a.r == b.r) && (a.g == b.g) && (a.b == b.b) && (a.a == b.a); }

// Texels of a map's depth below 1 (something drawn into it since its pass cleared it); -1 when unreadable
static int shMapTexelsWritten(const RblShadowMap *map)
{
    float *d = (float *)malloc((size_t)map->size*map->size*sizeof(float));
    if ((d == NULL) || !rtReadDepth(map->state->id, map->size, map->size, d)) { free(d); return -1; }
    int n = 0;
    for (int i = 0; i < map->size*map->size; i++) n += (d[i] < 1.0f);
    free(d);
    return n;
}

static void test_shadows_bad_input_is_refused_with_a_log_line_and_changes_nothing(void)
{
    RblShadowDesc bad;
    memset(&bad, 0, sizeof(bad));
    bad.size = 5;
    warnings = 0;
    RblShadowMap m = RblLoadShadowMap(bad);
    RT_CHECK(!RblIsShadowMapValid(m) && warnings == 1, "size 5 accepted");
    bad.size = 0; bad.normalBias = NAN;
    warnings = 0;
    m = RblLoadShadowMap(bad);
    RT_CHECK(!RblIsShadowMapValid(m) && warnings == 1, "NaN bias accepted");

    RblShadowDesc good;
    memset(&good, 0, sizeof(good));
    good.size = 64;
    RblShadowMap map = RblLoadShadowMap(good);
    RT_CHECK(RblIsShadowMapValid(map) && map.light == -1, "default shadow map failed");
    // Dim enough that the probe render below is not saturated (a changed ambient or exposure shows)
    RblLight lights[3] = { litPoint((Vector3){ 0, 0, 3 }, 1.0f, 5.0f), litDirectional((Vector3){ 0, 0, -1 }, 0.3f),
                           litSpot((Vector3){ 0, 0, 3 }, (Vector3){ 0, 0, -1 }, 10.0f, 85.0f, 1.0f) };
    RblScene scene, empty;
    memset(&scene, 0, sizeof(scene));
    memset(&empty, 0, sizeof(empty));
    scene.lights = lights; scene.lightCount = 3; scene.ambient = (Color){ 40, 40, 40, 255 };
    Vector3 o = { 0, 0, 0 };
    struct { const RblScene *scene; int index; Vector3 focus; float radius; const char *what; } cases[] = {
        { &scene, 0, o, 2.0f, "a point light" }, { &scene, 1, o, 0.0f, "directional without a focus radius" },
        { &scene, 1, (Vector3){ NAN, 0, 0 }, 2.0f, "NaN focus" }, { &scene, 1, o, INFINITY, "infinite radius" },
        { &scene, 2, o, 2.0f, "spot wider than 80 degrees" }, { NULL, 0, o, 2.0f, "no scene" },
        { &empty, 0, o, 2.0f, "a scene without lights" }, { &scene, 3, o, 2.0f, "index past the scene's lights" },
        { &scene, -1, o, 2.0f, "negative index" },
    };
    for (size_t i = 0; i < sizeof(cases)/sizeof(cases[0]); i++)
    {
        warnings = 0;
        RT_CHECK(!RblBeginShadowMap(&map, cases[i].scene, cases[i].index, cases[i].focus, cases[i].radius) && warnings == 1 && !map.state->begun && map.light == -1,
                 "%s accepted (%d log lines)", cases[i].what, warnings);
    }
    RblLight bent = litDirectional((Vector3){ 0, 0, 0 }, 1.0f);
    RblScene bentScene = empty;
    bentScene.lights = &bent; bentScene.lightCount = 1;
    warnings = 0;
    RT_CHECK(!RblBeginShadowMap(&map, &bentScene, 0, o, 2.0f) && warnings == 1 && !map.state->begun && map.light == -1, "zero direction accepted");

    // A receiver of every light type in the scene (so setting it logs nothing) and its floor
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.shading.lightFeatures = RblGetLightFeatures(lights, 3); desc.maxLights = 3; desc.shading.shadowMaps = 1;
    Shader lit = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(lit), "receiver failed to load");
    Texture2D white = solidTexture(WHITE);
    Material floor = LoadMaterialDefault();
    floor.shader = lit;
    floor.maps[MATERIAL_MAP_ALBEDO].texture = white;
    warnings = 0;
    RT_CHECK(RblSetScene(&scene) && warnings == 0, "scene without maps refused (%d log lines)", warnings);
    Color before = shProbe(floor);
    // A refused scene would show if any of it were applied: another ambient and exposure
    RblScene wrong = scene;
    wrong.ambient = (Color){ 200, 0, 0, 255 }; wrong.exposure = 0.5f;
    // Nested passes are refused; a pass in progress cannot be received
    RT_CHECK(RblBeginShadowMap(&map, &scene, 1, o, 2.0f), "good pass refused");
    RblShadowMap other = RblLoadShadowMap(good);
    warnings = 0;
    RT_CHECK(!RblBeginShadowMap(&other, &scene, 1, o, 2.0f) && warnings == 1 && !other.state->begun && other.light == -1, "nested shadow pass accepted");
    wrong.shadowMaps = &map; wrong.shadowMapCount = 1;
    warnings = 0;
    RT_CHECK(!RblSetScene(&wrong) && warnings == 1, "map still being rendered accepted");
    RblEndShadowMap(&map);
    Color after = shProbe(floor);
    RT_CHECK(shSameColor(after, before), "the refused scene (map being rendered) changed the frame: %d,%d,%d -> %d,%d,%d",
             before.r, before.g, before.b, after.r, after.g, after.b);
    scene.shadowMaps = &map; scene.shadowMapCount = 1;
    warnings = 0;
    RT_CHECK(RblSetScene(&scene) && warnings == 0, "rendered map refused (%d log lines)", warnings);
    before = shProbe(floor);
    RT_CHECK(before.r > 40 && before.r < 250, "probe floor %d: saturated or unlit, a changed scene would not show", before.r);
    RblShadowMap two[2] = { map, map };
    RblShadowMap many[RBL_MAX_SHADOWS + 1];
    for (int k = 0; k <= RBL_MAX_SHADOWS; k++) many[k] = map;
    struct { const RblShadowMap *maps; int count; int lightCount; const char *what; } refused[] = {
        { &other, 1, 3, "never-rendered map" }, { two, 2, 3, "two maps for the same light" },
        { many, RBL_MAX_SHADOWS + 1, 3, "more maps than RBL_MAX_SHADOWS" },
        { &map, 1, 1, "a map of a light the scene does not have (index 1 of 1 light)" },
        { two, 2, 3, "two maps for the same light (the second rendered for it too)" },
    };
    for (size_t i = 0; i < sizeof(refused)/sizeof(refused[0]); i++)
    {
        if (i == 4)
        {
            // other rendered for the same light as map: both valid, together refused
            RT_CHECK(RblBeginShadowMap(&other, &scene, 1, o, 2.0f), "second map's pass refused");
            RblEndShadowMap(&other);
            two[1] = other;
        }
        wrong.shadowMaps = refused[i].maps; wrong.shadowMapCount = refused[i].count; wrong.lightCount = refused[i].lightCount;
        warnings = 0;
        RT_CHECK(!RblSetScene(&wrong) && warnings == 1, "%s accepted (%d log lines)", refused[i].what, warnings);
        after = shProbe(floor);
        RT_CHECK(shSameColor(after, before), "the refused scene (%s) changed the frame: %d,%d,%d -> %d,%d,%d", refused[i].what,
                 before.r, before.g, before.b, after.r, after.g, after.b);
    }
    // Descs outside the limits
    warnings = 0;
    desc.shading.shadowMaps = RBL_MAX_SHADOWS + 1;
    RT_CHECK(!RblIsLitShaderValid(RblLoadLitShader(desc)) && warnings == 1, "shadowMaps above RBL_MAX_SHADOWS accepted");
    desc.shading.shadowMaps = 1; desc.shading.shadowFilter = RBL_SHADOW_MAX_FILTER + 1;
    warnings = 0;
    RT_CHECK(!RblIsLitShaderValid(RblLoadLitShader(desc)) && warnings == 1, "shadowFilter above the maximum accepted");
    // A Model drawn outside a pass (0.3: RblDrawModelShadow, refused) is a colour draw: no log line, it
    // lands in the current target, and no shadow map is written
    Model cube = LoadModelFromMesh(GenMeshCube(4, 4, 1));       // covers the centre pixels of the 8-unit view
    cube.materials[0].shader = lit;
    int writtenBefore = shMapTexelsWritten(&map);
    Camera3D top = shTopDown();
    RenderTexture2D rt = LoadRenderTexture(8, 8);
    warnings = 0;
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(top);
    RblDrawModel(cube, o, 1.0f, WHITE);
    EndMode3D();
    EndTextureMode();
    int drawWarnings = warnings;
    Image drawn = rtReadTarget(rt);
    int writtenAfter = shMapTexelsWritten(&map);
    RT_CHECK(drawWarnings == 0 && rtPixel(drawn, 4, 4).a == 255, "RblDrawModel outside a pass: %d log lines, centre alpha %d (expected a plain colour draw)",
             drawWarnings, rtPixel(drawn, 4, 4).a);
    RT_CHECK(writtenBefore == 0 && writtenAfter == 0, "RblDrawModel outside a pass wrote the shadow map (%d texels written, %d before)", writtenAfter, writtenBefore);
    UnloadImage(drawn);
    UnloadRenderTexture(rt);
    UnloadModel(cube);
    // Focus from a camera: bad input refused, a good one bounds the slice's corners
    Vector3 c; float r;
    warnings = 0;
    RT_CHECK(!RblShadowFocusFromCamera(litCamera(o, (Vector3){ 0, 0, -1 }), 1.5f, 5.0f, 2.0f, &c, &r) && warnings == 1, "far < near accepted");
    Camera3D cam = litCamera((Vector3){ 1, 2, 3 }, (Vector3){ 4, 2, -1 });
    RT_CHECK(RblShadowFocusFromCamera(cam, 16.0f/9.0f, 0.5f, 20.0f, &c, &r), "focus from camera refused");
    RblCameraFrame v = RblGetCameraFrame(cam);
    double t = tan(22.5*PI/180.0), worst = 0.0;
    for (int k = 0; k < 8; k++)
    {
        double dist = (k & 4)? 20.0 : 0.5, h = dist*t*((k & 1)? 1 : -1), w = dist*t*16.0/9.0*((k & 2)? 1 : -1);
        Vector3 p = { (float)(cam.position.x - v.back.x*dist + v.up.x*h + v.right.x*w), (float)(cam.position.y - v.back.y*dist + v.up.y*h + v.right.y*w),
                      (float)(cam.position.z - v.back.z*dist + v.up.z*h + v.right.z*w) };
        worst = fmax(worst, Vector3Distance(p, c)/r);
    }
    RT_CHECK(worst <= 1.0 + 1e-5 && worst > 0.95, "focus sphere does not tightly bound the slice (corner at %.4f radii)", worst);
    shClearScene();
    RblUnloadLitShader(&lit);
    MemFree(floor.maps);
    UnloadTexture(white);
    RblUnloadShadowMap(&map);
    RblUnloadShadowMap(&other);
}

// Degenerate lights and focus, casters of zero or huge size, receivers at the light: finite output
// in a float target, and no NaN anywhere
typedef struct ShHard { float size; } ShHard;
static void shHardCasters(Material m, Camera3D viewer, void *ctx)
{
    const ShHard *h = (const ShHard *)ctx;
    ShCard card = { { 0.2f, 0.1f, 0.5f }, h->size, 1 };
    shCardCasters(m, viewer, &card);
    RblDrawBillboard(viewer, m, litPlane());
}

static void test_shadows_hard_cases_stay_finite(void)
{
    Texture2D white = solidTexture(WHITE);
    struct { Vector3 dir; float radius; float size; int spot; const char *what; } cases[] = {
        { { 0, 0, -1 }, 4.0f, 2.0f, 0, "light straight down (light camera's up falls back)" },
        { { 0, 0, 1 }, 4.0f, 2.0f, 0, "light from below the floor" },
        { { 1, 0, -1e-4f }, 4.0f, 2.0f, 0, "grazing light" },
        { { 0.3f, 0.2f, -1 }, 1e-4f, 2.0f, 0, "tiny focus" },
        { { 0.3f, 0.2f, -1 }, 1e6f, 2.0f, 0, "huge focus" },
        { { 0.3f, 0.2f, -1 }, 4.0f, 0.0f, 0, "zero-size caster" },
        { { 0.3f, 0.2f, -1 }, 4.0f, 1e30f, 0, "huge caster (skipped)" },
        { { 0, 0, -1 }, 4.0f, 2.0f, 1, "spot light on the floor it lights" },
    };
    for (size_t i = 0; i < sizeof(cases)/sizeof(cases[0]); i++)
    {
        ShSetup s = shSetup(cases[i].dir);
        s.radius = cases[i].radius;
        if (cases[i].spot) { s.lights[0] = litSpot((Vector3){ 0.0f, 0.0f, 0.0f }, (Vector3){ 0.0f, 0.3f, -1.0f }, 20.0f, 40.0f, 4.0f); s.radius = 3.0f; }
        ShHard h = { cases[i].size };
        Image img = shRender(&s, shHardCasters, &h, white, false);
        int alpha0 = 0;
        for (int y = 0; y < SH_TARGET; y++) for (int x = 0; x < SH_TARGET; x++) if (rtPixel(img, x, y).a != 255) alpha0++;
        RT_CHECK(alpha0 == 0, "%s: %d pixels not written", cases[i].what, alpha0);
        UnloadImage(img);
        // Linear float output: finite everywhere
        RblLitShaderDesc desc;
        memset(&desc, 0, sizeof(desc));
        desc.maxLights = 1; desc.shading.lightFeatures = RblGetLightFeatures(s.lights, 1); desc.shading.shadowMaps = 1; desc.shading.linearOutput = true; desc.shading.brdf = RBL_BRDF_GGX;
        Shader lit = RblLoadLitShader(desc);
        RblShadowMap map = RblLoadShadowMap(s.shadow);
        Material cm = LoadMaterialDefault();
        cm.shader = lit; cm.maps[MATERIAL_MAP_ALBEDO].texture = white;
        rtSetMaterialValues(&cm, (RtMaterialValues){ .roughness = 1e-6f });
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = s.lights; scene.lightCount = 1; scene.ambient = s.ambient;
        RT_CHECK(RblBeginShadowMap(&map, &scene, 0, s.focus, s.radius), "%s: pass refused", cases[i].what);
        shHardCasters(cm, s.viewer, &h);
        RblEndShadowMap(&map);
        scene.shadowMaps = &map; scene.shadowMapCount = 1;
        RblSetScene(&scene);
        RenderTexture2D rt = litTarget(PIXELFORMAT_UNCOMPRESSED_R32G32B32A32);
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        BeginMode3D(s.camera);
        RblDrawBillboard(s.camera, cm, litPlane());
        EndMode3D();
        EndTextureMode();
        float *px = rtReadFloatPixels(rt.texture.id, LIT_TARGET, LIT_TARGET);
        int bad = 0;
        for (int k = 0; k < LIT_TARGET*LIT_TARGET*4; k++) if (!rtFinite(px[k]) || (px[k] < 0.0f)) bad++;
        RT_CHECK(bad == 0, "%s: %d non-finite or negative values", cases[i].what, bad);
        free(px);
        litTargetUnload(rt);
        MemFree(cm.maps);
        shClearScene();
        RblUnloadShadowMap(&map);
        RblUnloadLitShader(&lit);
    }
    printf("    %d hard cases: every pixel written, float output finite and non-negative\n", (int)(sizeof(cases)/sizeof(cases[0])));
    UnloadTexture(white);
}

// A raylib Model casts through RblDrawModel inside the pass (a cube hovering over the floor darkens its footprint)
static void shCubeCaster(Material m, Camera3D viewer, void *ctx)
{
    (void)m; (void)viewer;
    Model *cube = (Model *)ctx;
    RblDrawModel(*cube, (Vector3){ 0.0f, 0.0f, 1.0f }, 1.0f, WHITE);
}

static void test_shadows_raylib_model_casts_its_footprint(void)
{
    Texture2D white = solidTexture(WHITE);
    Model cube = LoadModelFromMesh(GenMeshCube(2.0f, 2.0f, 0.5f));
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    s.lights[0].direction = (Vector3){ 0.5f, 0.0f, -1.0f };
    ShSetup ref = s; ref.noShadow = true;
    Image base = shRender(&ref, NULL, NULL, white, false), img = shRender(&s, shCubeCaster, &cube, white, false);
    int thr = shThreshold(base, img);
    // Cube z in [0.75, 1.25] over [-1,1]^2: shadow spans x from -1 + 0.375 to 1 + 0.625 (shift 0.5 per unit height)
    int inside = 0, outside = 0, wrong = 0;
    for (int y = 0; y < SH_TARGET; y++)
        for (int x = 0; x < SH_TARGET; x++)
        {
            Vector2 p = shFloorAt(x, y);
            bool in = (p.x > -0.625f + 0.05f) && (p.x < 1.625f - 0.05f) && (fabsf(p.y) < 0.95f);
            bool out = (p.x < -0.625f - 0.05f) || (p.x > 1.625f + 0.05f) || (fabsf(p.y) > 1.05f);
            bool dark = rtPixel(img, x, y).r < thr;
            if (in) { inside++; if (!dark) wrong++; }
            if (out) { outside++; if (dark) wrong++; }
        }
    RT_CHECK(wrong == 0 && inside > 500, "cube footprint: %d of %d/%d pixels wrong", wrong, inside, outside);
    printf("    raylib Model caster: %d footprint pixels dark, %d pixels around it lit, %d wrong\n", inside, outside, wrong);
    if (wrong > 0) rtSaveImage(img, "cube");
    UnloadImage(base); UnloadImage(img);
    UnloadModel(cube);
    UnloadTexture(white);
}

// A shadow pass inside BeginTextureMode hands the render texture, its viewport and the matrices back
static void test_shadows_pass_restores_the_callers_target_and_matrices(void)
{
    RblShadowDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.size = 64;
    RblShadowMap map = RblLoadShadowMap(desc);
    RblLight sun = litDirectional((Vector3){ 0.2f, -1.0f, 0.1f }, 1.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1;
    RenderTexture2D rt = LoadRenderTexture(32, 16);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    Matrix view = rlGetMatrixModelview(), proj = rlGetMatrixProjection();
    RT_CHECK(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 2.0f), "pass refused");
    RblEndShadowMap(&map);
    // raylib 6.0's rlGetActiveFramebuffer answers 0 on ES 2 builds: the header asks GL itself there
    RT_CHECK(rbl__activeFramebuffer() == rt.id, "framebuffer %u after the pass, expected the render texture's %u", rbl__activeFramebuffer(), rt.id);
    Matrix v2 = rlGetMatrixModelview(), p2 = rlGetMatrixProjection();
    RT_CHECK(memcmp(&v2, &view, sizeof(Matrix)) == 0 && memcmp(&p2, &proj, sizeof(Matrix)) == 0, "matrices not restored");
    DrawRectangle(0, 0, 32, 16, RED);                   // must land in the render texture, all of it
    EndTextureMode();
    Image img = rtReadTarget(rt);
    RT_CHECK((rtPixel(img, 0, 0).r == 230) && (rtPixel(img, 31, 15).r == 230), "a draw after the pass missed the render texture (%d, %d)", rtPixel(img, 0, 0).r, rtPixel(img, 31, 15).r);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    RblUnloadShadowMap(&map);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_SHADOWS_TESTS \
    RT_TEST(test_shadows_opaque_card_darkens_its_analytic_footprint_within_a_texel), \
    RT_TEST(test_shadows_transparent_hole_in_a_sprite_lets_light_through_on_every_path), \
    RT_TEST(test_shadows_raylib_model_casts_its_footprint), \
    RT_TEST(test_shadows_no_acne_on_a_floor_lit_at_up_to_80_degrees), \
    RT_TEST(test_shadows_standing_card_casts_from_its_base_without_peter_panning), \
    RT_TEST(test_shadows_axis_locked_billboard_casts_under_a_light_straight_above), \
    RT_TEST_GLSL3(test_shadows_axis_tilt_is_the_same_on_cpu_and_gpu), \
    RT_TEST_GLSL3(test_shadows_forward_and_deferred_agree_within_2_of_255), \
    RT_TEST(test_shadows_bad_input_is_refused_with_a_log_line_and_changes_nothing), \
    RT_TEST(test_shadows_hard_cases_stay_finite), \
    RT_TEST(test_shadows_pass_restores_the_callers_target_and_matrices)
