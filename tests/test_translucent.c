// Translucent billboards on the GPU: sorted back to front (any submission order draws
// the same pixels, equal to the cards drawn one by one in depth order), the hybrid mode (solid texels
// write depth, the fringe blends over what lies behind without writing it), and bad sort settings.
// Reference: the alpha-blending equation (raylib's BLEND_ALPHA: c = src*a + dst*(1 - a) per 8-bit
// channel) applied to the unlit albedo (no lights, white ambient: the lit colour is the albedo), and
// the immediate path drawing the cards one call at a time in the right order.
// Also soft particles (fading by the scene depth behind). Included by gpu_tests.h.

#define SPR_TARGET 64

// Lambert program, no lights, white ambient: every texel shows its albedo
static Material sprMaterialOf(Texture2D texture, float alphaCutoff, bool instanced)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.instanced = instanced;
    Material m = LoadMaterialDefault();
    m.shader = RblLoadLitShader(d);
    m.maps[MATERIAL_MAP_ALBEDO].texture = texture;
    m.params[RBL_PARAM_ALPHA_CUTOFF] = alphaCutoff;
    return m;
}

static Material sprMaterial(Texture2D texture, float alphaCutoff) { return sprMaterialOf(texture, alphaCutoff, false); }

static void sprUnloadMaterial(Material *m)
{
    RblUnloadLitShader(&m->shader);
    m->shader.id = 0; m->shader.locs = NULL;
    MemFree(m->maps);
    m->maps = NULL;
}

static RblBillboard sprCard(float z, float x)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ x, 0.0f, z };
    b.size = (Vector2){ 1.2f, 1.2f };
    b.origin = (Vector2){ 0.6f, 0.6f };
    b.facing = RBL_FACING_FIXED;
    return b;
}

static Camera3D sprCamera(void)
{
    Camera3D c = frontCamera();
    c.position = (Vector3){ 0.0f, 0.0f, 4.0f };
    return c;
}

// One channel of raylib's alpha blending, in 8-bit units
static double sprBlend(double dst, double src, double a) { return src*a + dst*(1.0 - a); }

typedef struct SprCardSpec { float z; Color color; } SprCardSpec;

// Draws the cards (in the given order) through one batch with the given sort mode into a cleared target
static Image sprRenderBatch(Material *mats, const SprCardSpec *cards, const int *order, int n, int sort)
{
    RenderTexture2D rt = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
    RblBatch batch = RblLoadBatch(8);
    batch.sort = sort;
    BeginTextureMode(rt);
    ClearBackground((Color){ 0, 0, 0, 255 });
    BeginMode3D(sprCamera());
    RblBeginBatch(&batch, sprCamera());
    for (int i = 0; i < n; i++)
    {
        RblBillboard b = sprCard(cards[order[i]].z, 0.0f);
        RblBatchAdd(&batch, mats[order[i]], &b);
    }
    RblEndBatch(&batch);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    return img;
}

static void test_translucent_sorted_translucent_cards_draw_alike_in_any_submission_order(void)
{
    const SprCardSpec cards[3] = { { 0.0f, { 255, 0, 0, 128 } }, { -0.5f, { 0, 255, 0, 128 } }, { -1.0f, { 0, 0, 255, 128 } } };
    Texture2D tex[3];
    Material mats[3];
    for (int i = 0; i < 3; i++) { tex[i] = solidTexture(cards[i].color); mats[i] = sprMaterial(tex[i], 0.01f); }
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    // Expected centre pixel: black, then blue (farthest), green, red (nearest), each at alpha 128/255
    double a = 128.0/255.0, px[3] = { 0.0, 0.0, 0.0 };
    for (int k = 2; k >= 0; k--) { px[0] = sprBlend(px[0], cards[k].color.r, a); px[1] = sprBlend(px[1], cards[k].color.g, a); px[2] = sprBlend(px[2], cards[k].color.b, a); }
    // Reference: the immediate path, one call per card, farthest first
    RenderTexture2D rt = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
    BeginTextureMode(rt);
    ClearBackground((Color){ 0, 0, 0, 255 });
    BeginMode3D(sprCamera());
    for (int k = 2; k >= 0; k--) RblDrawBillboard(sprCamera(), mats[k], sprCard(cards[k].z, 0.0f));
    EndMode3D();
    EndTextureMode();
    Image ref = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    Color rc = rtPixel(ref, SPR_TARGET/2, SPR_TARGET/2);
    RT_CHECK((fabs(rc.r - px[0]) <= 2.0) && (fabs(rc.g - px[1]) <= 2.0) && (fabs(rc.b - px[2]) <= 2.0),
             "immediate back-to-front reference (%d %d %d), blending equation (%.1f %.1f %.1f)", rc.r, rc.g, rc.b, px[0], px[1], px[2]);
    const int orders[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
    int differing = 0, worst = 0;
    for (int o = 0; o < 6; o++)
    {
        Image img = sprRenderBatch(mats, cards, orders[o], 3, RBL_SORT_BACK_TO_FRONT);
        for (int y = 0; y < SPR_TARGET; y++)
            for (int x = 0; x < SPR_TARGET; x++)
            {
                Color p = rtPixel(img, x, y), q = rtPixel(ref, x, y);
                int e = abs(p.r - q.r) + abs(p.g - q.g) + abs(p.b - q.b);
                if (e > 0) differing++;
                if (e > worst) worst = e;
            }
        if (rtFailuresInCurrentTest() == 0 && worst > 0) rtSaveImage(img, "sorted");
        UnloadImage(img);
    }
    RT_CHECK(differing == 0, "sorted batches differ from the back-to-front reference in %d pixels (worst %d)", differing, worst);
    // Unsorted, submitted front to back: the depth test drops the cards behind (what sorting fixes)
    Image unsorted = sprRenderBatch(mats, cards, orders[0], 3, RBL_SORT_NONE);
    Color u = rtPixel(unsorted, SPR_TARGET/2, SPR_TARGET/2);
    RT_CHECK(abs(u.r - rc.r) + abs(u.g - rc.g) + abs(u.b - rc.b) > 60, "unsorted front-to-back (%d %d %d) should differ from sorted (%d %d %d)", u.r, u.g, u.b, rc.r, rc.g, rc.b);
    printf("    3 cards at alpha 128/255: sorted, all 6 submission orders = immediate back-to-front (%d %d %d; equation %.1f %.1f %.1f); unsorted front-to-back (%d %d %d)\n",
           rc.r, rc.g, rc.b, px[0], px[1], px[2], u.r, u.g, u.b);
    UnloadImage(unsorted);
    UnloadImage(ref);
    for (int i = 0; i < 3; i++) { sprUnloadMaterial(&mats[i]); UnloadTexture(tex[i]); }
}

// A tree card with solid bark and translucent holes in front of a smoke puff submitted after it: the
// hybrid mode shows the smoke through the holes, the plain batch hides it behind the holes' depth
static void test_translucent_hybrid_smoke_behind_a_tree_shows_through_its_holes(void)
{
    // Tree: 8x8, solid brown with a 4x4 translucent (alpha 64) window in the middle; nearest filtering
    Image treeImg = GenImageColor(8, 8, (Color){ 120, 80, 40, 255 });
    ImageDrawRectangle(&treeImg, 2, 2, 4, 4, (Color){ 40, 160, 40, 64 });
    Texture2D tree = LoadTextureFromImage(treeImg);
    SetTextureFilter(tree, TEXTURE_FILTER_POINT);
    UnloadImage(treeImg);
    Texture2D smoke = solidTexture((Color){ 200, 200, 220, 160 });
    Material mats[2] = { sprMaterial(tree, 0.01f), sprMaterial(smoke, 0.01f) };
    const SprCardSpec cards[2] = { { 0.0f, { 0 } }, { -1.0f, { 0 } } };
    const int order[2] = { 0, 1 };          // tree first, smoke behind it second: the hard order
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    // Expected in the window: black, smoke (alpha 160), then the tree's window texel (alpha 64)
    double as = 160.0/255.0, at = 64.0/255.0;
    double expect[3] = { sprBlend(sprBlend(0.0, 200.0, as), 40.0, at), sprBlend(sprBlend(0.0, 200.0, as), 160.0, at), sprBlend(sprBlend(0.0, 220.0, as), 40.0, at) };
    double hidden[3] = { sprBlend(0.0, 40.0, at), sprBlend(0.0, 160.0, at), sprBlend(0.0, 40.0, at) };
    const char *names[3] = { "none", "back-to-front", "hybrid" };
    Color centre[3], bark[3];
    for (int mode = 0; mode < 3; mode++)
    {
        Image img = sprRenderBatch(mats, cards, order, 2, mode);
        centre[mode] = rtPixel(img, SPR_TARGET/2, SPR_TARGET/2);
        // A bark texel: the card spans 1.2 units at distance 4 (fovy 45): about 23 pixels; bark near its left edge
        bark[mode] = rtPixel(img, SPR_TARGET/2 - 9, SPR_TARGET/2);
        if (mode == 2) { bool ok = (fabs(centre[2].r - expect[0]) <= 2.0); if (!ok) rtSaveImage(img, "hybrid"); }
        UnloadImage(img);
        printf("    %-14s window (%3d %3d %3d), bark (%3d %3d %3d)\n", names[mode], centre[mode].r, centre[mode].g, centre[mode].b, bark[mode].r, bark[mode].g, bark[mode].b);
    }
    printf("    expected window: smoke then tree (%.1f %.1f %.1f); smoke hidden (%.1f %.1f %.1f)\n", expect[0], expect[1], expect[2], hidden[0], hidden[1], hidden[2]);
    RT_CHECK((fabs(centre[2].r - expect[0]) <= 2.0) && (fabs(centre[2].g - expect[1]) <= 2.0) && (fabs(centre[2].b - expect[2]) <= 2.0),
             "hybrid window (%d %d %d), expected (%.1f %.1f %.1f)", centre[2].r, centre[2].g, centre[2].b, expect[0], expect[1], expect[2]);
    RT_CHECK((fabs(centre[0].r - hidden[0]) <= 2.0) && (fabs(centre[0].g - hidden[1]) <= 2.0), "plain batch window (%d %d %d): expected the smoke hidden (%.1f %.1f %.1f)",
             centre[0].r, centre[0].g, centre[0].b, hidden[0], hidden[1], hidden[2]);
    for (int mode = 0; mode < 3; mode++) RT_CHECK((bark[mode].r == 120) && (bark[mode].g == 80) && (bark[mode].b == 40), "%s: bark (%d %d %d) is not the opaque bark colour", names[mode], bark[mode].r, bark[mode].g, bark[mode].b);
    // The hybrid's fringe pass turns depth writes off; they are back on afterwards (raylib's default)
    unsigned char mask = 0;
    void (*getBooleanv)(unsigned int, unsigned char *); void *p = rtGlProc("glGetBooleanv"); memcpy(&getBooleanv, &p, sizeof(p));
    getBooleanv(0x0B72 /* GL_DEPTH_WRITEMASK */, &mask);
    RT_CHECK(mask == 1, "depth writes left off after a hybrid batch");
    for (int i = 0; i < 2; i++) sprUnloadMaterial(&mats[i]);
    UnloadTexture(tree); UnloadTexture(smoke);
}

static void test_translucent_bad_sort_settings_are_refused_and_draw_nothing(void)
{
    Texture2D white = solidTexture(WHITE);
    Material m = sprMaterial(white, 0.0f);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    const int sorts[4] = { -1, 3, RBL_SORT_HYBRID, RBL_SORT_HYBRID };
    const float solids[4] = { 0.0f, 0.0f, NAN, 1.5f };
    for (int k = 0; k < 4; k++)
    {
        RenderTexture2D rt = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
        RblBatch batch = RblLoadBatch(4);
        BeginTextureMode(rt);
        ClearBackground(BLACK);
        BeginMode3D(sprCamera());
        RblBeginBatch(&batch, sprCamera());
        RblBillboard b = sprCard(0.0f, 0.0f);
        RblBatchAdd(&batch, m, &b);
        batch.sort = sorts[k]; batch.solidAlpha = solids[k];
        warnings = 0;
        RblEndBatch(&batch);
        int logged = warnings;
        EndMode3D();
        EndTextureMode();
        Image img = rtReadTarget(rt);
        Color c = rtPixel(img, SPR_TARGET/2, SPR_TARGET/2);
        RT_CHECK((logged == 1) && (c.r == 0) && (c.g == 0) && (c.b == 0), "sort %d solidAlpha %g: %d log lines, centre (%d %d %d): expected 1 line, nothing drawn",
                 sorts[k], solids[k], logged, c.r, c.g, c.b);
        // The batch ended: it begins again normally
        RT_CHECK(RblBeginBatch(&batch, sprCamera()), "batch unusable after a refused end");
        batch.sort = RBL_SORT_NONE; batch.solidAlpha = 0.0f;
        RblEndBatch(&batch);
        UnloadImage(img);
        RblUnloadBatch(&batch);
        UnloadRenderTexture(rt);
    }
    sprUnloadMaterial(&m);
    UnloadTexture(white);
}

// The instanced path's sort option: three tinted instances of one translucent texture, every array
// order, against the immediate path drawing them one by one farthest first
static void test_translucent_instanced_sort_draws_alike_in_any_array_order(void)
{
    Texture2D glass = solidTexture((Color){ 255, 255, 255, 128 });
    Material m = sprMaterial(glass, 0.01f), mi = sprMaterialOf(glass, 0.01f, true);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    const float z[3] = { 0.0f, -0.5f, -1.0f };
    const Color tint[3] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 } };
    RenderTexture2D rt = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(sprCamera());
    for (int k = 2; k >= 0; k--) { RblBillboard b = sprCard(z[k], 0.0f); b.tint = tint[k]; RblDrawBillboard(sprCamera(), m, b); }
    EndMode3D();
    EndTextureMode();
    Image ref = rtReadTarget(rt);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(8);
    const int orders[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
    int differing = 0;
    Color unsortedCentre = BLANK;
    for (int o = 0; o < 7; o++)
    {
        RblInstance in[3];
        memset(in, 0, sizeof(in));
        for (int i = 0; i < 3; i++)
        {
            int k = orders[(o < 6)? o : 0][i];
            in[i].position = (Vector3){ 0.0f, 0.0f, z[k] };
            in[i].size = (Vector2){ 1.2f, 1.2f }; in[i].origin = (Vector2){ 0.6f, 0.6f };
            in[i].tint = tint[k];
        }
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = RBL_FACING_FIXED;
        d.sort = (o < 6)? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE;     // the last: front to back, unsorted
        BeginTextureMode(rt);
        ClearBackground(BLACK);
        BeginMode3D(sprCamera());
        RT_CHECK(RblDrawInstanced(&buf, sprCamera(), mi, d, in, 3) == 3, "instanced draw refused");
        EndMode3D();
        EndTextureMode();
        Image img = rtReadTarget(rt);
        if (o == 6) unsortedCentre = rtPixel(img, SPR_TARGET/2, SPR_TARGET/2);
        else
            for (int y = 0; y < SPR_TARGET; y++)
                for (int x = 0; x < SPR_TARGET; x++)
                {
                    Color p = rtPixel(img, x, y), q = rtPixel(ref, x, y);
                    if (abs(p.r - q.r) + abs(p.g - q.g) + abs(p.b - q.b) > 0) differing++;
                }
        UnloadImage(img);
    }
    Color rc = rtPixel(ref, SPR_TARGET/2, SPR_TARGET/2);
    RT_CHECK(differing == 0, "sorted instanced draws differ from the immediate back-to-front reference in %d pixels", differing);
    RT_CHECK(abs(unsortedCentre.g - rc.g) + abs(unsortedCentre.b - rc.b) > 40, "unsorted front-to-back instances (%d %d %d) should differ from sorted (%d %d %d)",
             unsortedCentre.r, unsortedCentre.g, unsortedCentre.b, rc.r, rc.g, rc.b);
    printf("    instanced, sorted: all 6 array orders = immediate back-to-front (%d %d %d); unsorted front-to-back (%d %d %d)\n",
           rc.r, rc.g, rc.b, unsortedCentre.r, unsortedCentre.g, unsortedCentre.b);
    UnloadImage(ref);
    UnloadRenderTexture(rt);
    RblUnloadInstanceBuffer(&buf);
    sprUnloadMaterial(&m);
    sprUnloadMaterial(&mi);
    UnloadTexture(glass);
}

// A soft-particle material: white, never cut (faded texels blend to nothing), fade distance 0.5
static Material sprSoftPuff(Texture2D white)
{
    RblLitShaderDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.softParticles = true;
    Material puff = LoadMaterialDefault();
    puff.shader = RblLoadLitShader(sd);
    puff.maps[MATERIAL_MAP_ALBEDO].texture = white;
    puff.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;
    puff.params[RBL_PARAM_SOFT_DISTANCE] = 0.5f;
    return puff;
}

// Centre pixel of a white soft card `delta` in front of the plane z = 0, drawn alone over black into out
static Color sprSoftCentre(Camera3D cam, Material puff, RenderTexture2D out, float delta)
{
    BeginTextureMode(out);
    ClearBackground(BLACK);
    BeginMode3D(cam);
    RblDrawBillboard(cam, puff, sprCard(delta, 0.0f));
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(out);
    Color c = rtPixel(img, SPR_TARGET/2, SPR_TARGET/2);
    UnloadImage(img);
    return c;
}

// Soft particles: an opaque wall drawn into a scene target (colour + depth texture); a white card at
// distance delta in front of it, drawn into another target over black with the wall's depth in the
// scene, shows 255*clamp(delta/fade, 0, 1) (the fade's definition), for perspective and orthographic
// cameras; without a scene depth it is not faded; a soft G-buffer variant is refused.
static void test_translucent_soft_particles_fade_by_depth_distance_to_the_scene(void)
{
    Texture2D white = solidTexture(WHITE);
    Material wall = sprMaterial(white, 0.0f);
    Material puff = sprSoftPuff(white);
    RT_CHECK(RblIsLitShaderValid(puff.shader), "soft variant did not compile");
    RenderTexture2D sceneTarget = RblLoadSceneTarget(SPR_TARGET, SPR_TARGET);
    RT_CHECK(sceneTarget.id != 0 && sceneTarget.depth.id != 0, "scene target refused");
    const float deltas[7] = { -0.2f, 0.0f, 0.05f, 0.1f, 0.25f, 0.4f, 0.8f };
    double worst = 0.0;
    for (int ortho = 0; ortho < 2; ortho++)
    {
        Camera3D cam = sprCamera();
        if (ortho) { cam.projection = CAMERA_ORTHOGRAPHIC; cam.fovy = 3.0f; }
        RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
        BeginTextureMode(sceneTarget);
        ClearBackground(BLACK);
        BeginMode3D(cam);
        RblBillboard w = sprCard(0.0f, 0.0f);
        w.size = (Vector2){ 20.0f, 20.0f }; w.origin = (Vector2){ 10.0f, 10.0f };
        RblDrawBillboard(cam, wall, w);
        EndMode3D();
        EndTextureMode();
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.ambient = WHITE;
        scene.depth = sceneTarget.depth;
        RT_CHECK(RblSetScene(&scene), "scene with depth refused");
        RenderTexture2D out = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
        for (int k = 0; k < 7; k++)
        {
            Color c = sprSoftCentre(cam, puff, out, deltas[k]);
            double fade = fmin(fmax(deltas[k]/0.5, 0.0), 1.0), want = 255.0*fade;
            worst = fmax(worst, fabs(c.r - want));
            RT_CHECK(fabs(c.r - want) <= 2.0, "%s, card %.2f in front of the wall: %d, expected %.1f (fade %.3f)", ortho? "ortho" : "persp", deltas[k], c.r, want, fade);
            printf("    %-5s card %5.2f in front: centre %3d, expected %5.1f\n", ortho? "ortho" : "persp", deltas[k], c.r, want);
        }
        // No scene depth: no fade (a card 0.05 in front shows at full strength)
        scene.depth.id = 0; scene.depth.width = scene.depth.height = 0;
        RT_CHECK(RblSetScene(&scene), "scene without depth refused");
        Color full = sprSoftCentre(cam, puff, out, 0.05f);
        RT_CHECK(full.r == 255, "no scene depth: centre %d, expected 255 (no fade)", full.r);
        UnloadRenderTexture(out);
    }
    printf("    soft particles: worst |centre - 255*clamp(delta/0.5)| %.1f/255 over 7 distances x 2 projections\n", worst);
    RblLitShaderDesc bad;
    memset(&bad, 0, sizeof(bad));
    bad.softParticles = true;
    bad.deferred = true;
    warnings = 0;
    Shader refused = RblLoadLitShader(bad);
    RT_CHECK((refused.id == 0) && (warnings == 1), "soft G-buffer variant: id %u, %d log lines", refused.id, warnings);
    UnloadRenderTexture(sceneTarget);
    sprUnloadMaterial(&wall);
    sprUnloadMaterial(&puff);
    UnloadTexture(white);
}

// Soft particles in a plain raylib frame: the opaque wall between RblBeginSceneDepth and
// RblEndSceneDepth (two added lines), then the soft card drawn as usual. The card fades by its
// distance to the wall as over a RblLoadSceneTarget (255*clamp(delta/0.5)); the world's depth reached
// the target (a card behind the wall is hidden); the background shows where the world drew nothing;
// the scene target follows targets of other sizes
static void test_translucent_soft_particles_in_a_plain_frame_with_two_added_lines(void)
{
    Texture2D white = solidTexture(WHITE);
    Material wall = sprMaterial(white, 0.0f);
    wall.maps[MATERIAL_MAP_ALBEDO].color = (Color){ 0, 0, 255, 255 };
    Material puff = sprSoftPuff(white);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    const float deltas[6] = { -0.2f, 0.0f, 0.1f, 0.25f, 0.4f, 0.8f };
    const int sizes[3] = { SPR_TARGET, 48, 80 };
    double worst = 0.0;
    for (int si = 0; si < 3; si++)
    for (int ortho = 0; ortho < 2; ortho++)
    {
        Camera3D cam = sprCamera();
        if (ortho) { cam.projection = CAMERA_ORTHOGRAPHIC; cam.fovy = 3.0f; }
        RenderTexture2D screen = LoadRenderTexture(sizes[si], sizes[si]);     // stands for the window
        for (int k = 0; k < 6; k++)
        {
            BeginTextureMode(screen);
            ClearBackground(RED);
            warnings = 0;
            bool began = RblBeginSceneDepth();
            BeginMode3D(cam);
            RblBillboard w = sprCard(0.0f, 0.0f);
            w.size = (Vector2){ 2.0f, 2.0f }; w.origin = (Vector2){ 1.0f, 1.0f };      // leaves red corners
            RblDrawBillboard(cam, wall, w);
            EndMode3D();
            RblEndSceneDepth();
            BeginMode3D(cam);
            RblDrawBillboard(cam, puff, sprCard(deltas[k], 0.0f));
            EndMode3D();
            EndTextureMode();
            RT_CHECK(began && warnings == 0, "size %d: RblBeginSceneDepth %d, %d lines (%s)", sizes[si], began, warnings, lastWarning);
            Image img = rtReadTarget(screen);
            Color c = rtPixel(img, sizes[si]/2, sizes[si]/2), corner = rtPixel(img, 1, 1);
            UnloadImage(img);
            // Over the blue wall: white*fade + blue*(1 - fade) in red; behind the wall (delta < 0): the wall
            double fade = fmin(fmax(deltas[k]/0.5, 0.0), 1.0), want = 255.0*fade;
            worst = fmax(worst, fabs(c.r - want));
            RT_CHECK(fabs(c.r - want) <= 2.0 && c.b >= 253, "size %d %s, card %.2f in front: centre (%d,%d,%d), red expected %.1f over blue",
                     sizes[si], ortho? "ortho" : "persp", deltas[k], c.r, c.g, c.b, want);
            RT_CHECK(corner.r == RED.r && corner.g == RED.g && corner.b == RED.b, "size %d: the target's background under no world should show (%d,%d,%d)", sizes[si], corner.r, corner.g, corner.b);
        }
        RT_CHECK(rbl__state.capture.target.texture.width == sizes[si], "the scene target is %d wide for a %d target", rbl__state.capture.target.texture.width, sizes[si]);
        UnloadRenderTexture(screen);
    }
    printf("    two-line frame: worst |centre - 255*clamp(delta/0.5)| %.1f/255 over 6 distances x 2 projections x 3 target sizes\n", worst);
    sprUnloadMaterial(&wall);
    sprUnloadMaterial(&puff);
    UnloadTexture(white);
}


// Soft particles over a G-buffer's depth: the wall goes through the geometry pass, the card reads
// RblGBuffer.depth through the scene, with the same expectation as over a RblLoadSceneTarget
static void test_translucent_soft_particles_read_a_gbuffer_depth(void)
{
    Texture2D white = solidTexture(WHITE);
    RblLitShaderDesc geoDesc;
    memset(&geoDesc, 0, sizeof(geoDesc));
    RblGBuffer g = RblLoadGBuffer(defGBufferDesc(&geoDesc, SPR_TARGET, SPR_TARGET));
    geoDesc.deferred = true;
    Material wall = LoadMaterialDefault();
    wall.shader = RblLoadLitShader(geoDesc);
    wall.maps[MATERIAL_MAP_ALBEDO].texture = white;
    Material puff = sprSoftPuff(white);
    RT_CHECK(RblIsGBufferValid(g) && RblIsLitShaderValid(wall.shader) && RblIsLitShaderValid(puff.shader), "G-buffer or programs failed");
    Camera3D cam = sprCamera();
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    RT_CHECK(RblBeginGBuffer(&g, cam), "geometry pass refused");
    RblBillboard w = sprCard(0.0f, 0.0f);
    w.size = (Vector2){ 20.0f, 20.0f }; w.origin = (Vector2){ 10.0f, 10.0f };
    RblDrawBillboard(cam, wall, w);
    RblEndGBuffer(&g);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.ambient = WHITE;
    scene.depth = g.depth;
    RT_CHECK(RblSetScene(&scene), "scene with the G-buffer depth refused");
    RenderTexture2D out = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
    const float deltas[4] = { -0.1f, 0.1f, 0.25f, 0.6f };
    for (int k = 0; k < 4; k++)
    {
        Color c = sprSoftCentre(cam, puff, out, deltas[k]);
        double want = 255.0*fmin(fmax(deltas[k]/0.5, 0.0), 1.0);
        RT_CHECK(fabs(c.r - want) <= 2.0, "G-buffer depth, card %.2f in front: %d, expected %.1f", deltas[k], c.r, want);
        printf("    G-buffer depth: card %5.2f in front: centre %3d, expected %5.1f\n", deltas[k], c.r, want);
    }
    UnloadRenderTexture(out);
    RblUnloadGBuffer(&g);
    RblUnloadLitShader(&wall.shader); MemFree(wall.maps);
    RblUnloadLitShader(&puff.shader); MemFree(puff.maps);
    UnloadTexture(white);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_TRANSLUCENT_TESTS \
    RT_TEST(test_translucent_sorted_translucent_cards_draw_alike_in_any_submission_order), \
    RT_TEST(test_translucent_hybrid_smoke_behind_a_tree_shows_through_its_holes), \
    RT_TEST(test_translucent_bad_sort_settings_are_refused_and_draw_nothing), \
    RT_TEST_GLSL3(test_translucent_instanced_sort_draws_alike_in_any_array_order), \
    RT_TEST(test_translucent_soft_particles_fade_by_depth_distance_to_the_scene), \
    RT_TEST(test_translucent_soft_particles_in_a_plain_frame_with_two_added_lines), \
    RT_TEST_GLSL3(test_translucent_soft_particles_read_a_gbuffer_depth)
