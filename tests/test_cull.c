// Batch culling (RblBatch.noCull, .culled): billboards wholly outside the camera's frustum, or
// outside a shadow pass's light, are neither expanded nor drawn. The pictures with culling on and
// off are identical (every channel, whole target); each billboard drawn alone is culled only where
// its picture alone is empty; the far ones are culled (the count fails without culling); a
// batch begun in another camera's 3D mode culls nothing rather than culling wrongly.
// Included by test_gpu_main.c (after test_shadows.c).

// A mixed set: near the view (every facing, rotations, mirrors, long CAMERA_PLANE ups), straddling
// its edges, pivots outside with quads reaching in, behind the camera, and far away on every side
#define CULL_SET 72
#define CULL_FAR 24         // the last CULL_FAR are far outside: culled whatever the facing
static void cullSet(RblBillboard set[CULL_SET])
{
    unsigned int seed = 91u;
    for (int i = 0; i < CULL_SET; i++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.facing = i%4;
        b.size = (Vector2){ rtRandomRange(&seed, 0.3f, 1.5f), rtRandomRange(&seed, 0.3f, 1.5f) };
        b.origin = (Vector2){ b.size.x*rtRandomRange(&seed, 0.0f, 1.0f), b.size.y*rtRandomRange(&seed, 0.0f, 1.0f) };
        b.rotation = (i%3 == 0)? rtRandomRange(&seed, -180.0f, 180.0f) : 0.0f;
        if (i%5 == 1) b.size.x = -b.size.x;
        b.axis = (b.facing == RBL_FACING_FIXED)? (Vector3){ rtRandomRange(&seed, -1, 1), rtRandomRange(&seed, -1, 1), 1.0f } : (Vector3){ 0, 1, 0 };
        b.up = (b.facing == RBL_FACING_CAMERA_PLANE)? (Vector3){ 0.0f, rtRandomRange(&seed, 0.5f, 3.0f), 0.0f } : (Vector3){ 0, 0, 0 };
        b.roundness = 0.5f;
        float x = rtRandomRange(&seed, -3.5f, 3.5f), y = rtRandomRange(&seed, -3.0f, 3.0f), z = rtRandomRange(&seed, -4.0f, 2.0f);
        if (i < 24) b.position = (Vector3){ x*0.6f, y*0.6f, z };                         // mostly inside
        else if (i < 36) b.position = (Vector3){ (x < 0)? x - 1.8f : x + 1.8f, y, z };    // around the side edges
        else if (i < 42)
        {
            // Pivot well outside, quad reaching in: a wide card whose pivot sits at its far end
            b.facing = RBL_FACING_CAMERA_POSITION; b.rotation = 0.0f;
            b.size = (Vector2){ 6.0f, 0.8f };
            b.position = (Vector3){ (i%2)? 5.0f : -5.0f, y*0.3f, 0.0f };
            b.origin = (Vector2){ (i%2)? 5.8f : 0.2f, 0.4f };
        }
        else if (i < 45) b.position = (Vector3){ x, y, 7.0f + (float)(i - 42) };             // behind the camera
        else if (i < 48)
        {
            // CAMERA_PLANE with a long up from below the view: the quad's height is size.y |up|
            b.facing = RBL_FACING_CAMERA_PLANE; b.rotation = 0.0f;
            b.size = (Vector2){ 1.0f, 1.0f }; b.origin = (Vector2){ 0.5f, 0.0f };
            b.up = (Vector3){ 0.0f, 6.0f, 0.0f };
            b.position = (Vector3){ x*0.5f, -5.0f, -1.0f };
        }
        else
        {
            float far = 60.0f + 10.0f*(float)(i%3);
            int side = i%6;
            b.position = (side == 0)? (Vector3){ far, y, z } : (side == 1)? (Vector3){ -far, y, z } : (side == 2)? (Vector3){ x, far, z } :
                         (side == 3)? (Vector3){ x, -far, z } : (side == 4)? (Vector3){ x, y, -9000.0f } : (Vector3){ x, y, far };      // beyond rlgl's far plane (4000), behind
        }
        set[i] = b;
    }
}

// The set (or set[only] alone when only >= 0) batched into a fresh target; *culled gets the count
static Image cullRender(Scene *s, Camera3D cam, const RblBillboard *set, int only, bool noCull, bool otherMode, int *culled)
{
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    RblBatch batch = RblLoadBatch(CULL_SET);
    batch.noCull = noCull;
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    // otherMode: the 3D mode's camera is not the batch's (moved aside): what the batch's camera
    // would cull is not what this view sees
    Camera3D mode = cam;
    if (otherMode) { mode.position.x += 4.0f; mode.target.x += 4.0f; }
    BeginMode3D(mode);
    RT_CHECK(RblBeginBatch(&batch, cam), "batch refused");
    int added = 0;
    for (int i = 0; i < CULL_SET; i++) if ((only < 0) || (i == only)) added += RblBatchAdd(&batch, s->material, &set[i]);
    RT_CHECK(added == ((only < 0)? CULL_SET : 1) && batch.count == added && batch.skipped == 0, "added %d, count %d, skipped %d", added, batch.count, batch.skipped);
    *culled = batch.culled;
    RblEndBatch(&batch);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    return img;
}

// Pixels that differ in any channel
static int cullDiff(Image a, Image b)
{
    int n = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++)
        {
            Color p = rtPixel(a, x, y), q = rtPixel(b, x, y);
            if ((p.r != q.r) || (p.g != q.g) || (p.b != q.b) || (p.a != q.a)) n++;
        }
    return n;
}

static int cullLitPixels(Image a)
{
    int n = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++) { Color p = rtPixel(a, x, y); if (p.r | p.g | p.b) n++; }
    return n;
}

static void test_cull_batches_skip_what_the_camera_cannot_see_and_draw_the_same_picture(void)
{
    Scene s = sceneLoad((Color){ 220, 180, 140, 255 }, normalTexel(0, 0, 1), false);
    RblLight l = rtPointLight((Vector3){ 1, 2, 4 }, 20.0f);
    RT_CHECK(renderSetLights(&l, 1, (Color){ 60, 60, 60, 255 }), "scene rejected");
    RblBillboard set[CULL_SET];
    cullSet(set);
    for (int ortho = 0; ortho < 2; ortho++)
    {
        Camera3D cam = frontCamera();
        if (ortho) { cam.projection = CAMERA_ORTHOGRAPHIC; cam.fovy = 6.0f; }
        int culledOn = -1, culledOff = -1;
        Image on = cullRender(&s, cam, set, -1, false, false, &culledOn), off = cullRender(&s, cam, set, -1, true, false, &culledOff);
        int diff = cullDiff(on, off), lit = cullLitPixels(off);
        // Each billboard alone: culled only where its picture alone is empty; the far ones culled
        int wrong = 0, farKept = 0, nearCulled = 0;
        for (int i = 0; i < CULL_SET; i++)
        {
            int c = -1, c0 = -1;
            Image alone = cullRender(&s, cam, set, i, true, false, &c0);
            int visible = cullLitPixels(alone);
            UnloadImage(alone);
            Image culledAlone = cullRender(&s, cam, set, i, false, false, &c);
            UnloadImage(culledAlone);
            if ((c == 1) && (visible > 0)) { wrong++; printf("    billboard %d culled but draws %d pixels\n", i, visible); }
            if ((i >= CULL_SET - CULL_FAR) && (c != 1)) farKept++;
            if ((i < CULL_SET - CULL_FAR) && (c == 1)) nearCulled++;
        }
        printf("    %s: %d of %d culled (culling off: %d), %d far ones kept, %d near ones culled (each empty alone); %d lit pixels, %d differ\n",
               ortho? "orthographic" : "perspective", culledOn, CULL_SET, culledOff, farKept, nearCulled, lit, diff);
        RT_CHECK(lit > 300, "%s: picture nearly empty (%d lit pixels)", ortho? "ortho" : "persp", lit);
        RT_CHECK(diff == 0, "%s: %d pixels differ with culling on and off", ortho? "ortho" : "persp", diff);
        RT_CHECK(wrong == 0, "%s: %d visible billboards culled", ortho? "ortho" : "persp", wrong);
        RT_CHECK(culledOff == 0 && culledOn >= CULL_FAR && farKept == 0, "%s: culled %d (off %d), far kept %d", ortho? "ortho" : "persp", culledOn, culledOff, farKept);
        if (diff > 0) { rtSaveImage(on, "cull_on"); rtSaveImage(off, "cull_off"); }
        UnloadImage(on); UnloadImage(off);
        // Begun inside another camera's 3D mode (or outside any): the batch's camera is not the view
        // it draws with, so it culls nothing (never what that view sees)
        int culledOther = -1;
        Image other = cullRender(&s, cam, set, -1, false, true, &culledOther), otherOff = cullRender(&s, cam, set, -1, true, true, &culledOff);
        RT_CHECK(culledOther == 0 && cullDiff(other, otherOff) == 0, "%s: in another camera's mode %d culled, %d pixels differ", ortho? "ortho" : "persp", culledOther, cullDiff(other, otherOff));
        UnloadImage(other); UnloadImage(otherOff);
    }
    sceneUnload(s);
}

// Shadow pass: casters outside the light's four sides are culled; the floor's shadows are the same
typedef struct CullShadowCtx { bool noCull; int culled, count; } CullShadowCtx;
static void cullShadowCasters(Material m, Camera3D viewer, void *ctx)
{
    CullShadowCtx *c = (CullShadowCtx *)ctx;
    RblBatch batch = RblLoadBatch(64);
    batch.noCull = c->noCull;
    RblBeginBatch(&batch, viewer);
    unsigned int seed = 7u;
    for (int i = 0; i < 48; i++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.size = (Vector2){ 0.8f, 0.8f }; b.origin = (Vector2){ 0.4f, 0.0f };
        b.facing = (i%2)? RBL_FACING_AXIS : RBL_FACING_FIXED;
        b.axis = (b.facing == RBL_FACING_AXIS)? (Vector3){ 0.0f, 0.0f, 1.0f } : (Vector3){ 0.0f, 0.0f, 1.0f };
        b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
        float x = rtRandomRange(&seed, -3.0f, 3.0f), y = rtRandomRange(&seed, -3.0f, 3.0f);
        if (i >= 32) x += (i%2)? 80.0f : -80.0f;       // 16 far outside the light's sides
        b.position = (Vector3){ x, y, 0.6f };
        RblBatchAdd(&batch, m, &b);
    }
    c->culled = batch.culled;
    c->count = batch.count;
    RblEndBatch(&batch);
    RblUnloadBatch(&batch);
}

static void test_cull_shadow_pass_batches_skip_casters_outside_the_light_and_cast_the_same_shadows(void)
{
    ShSetup s = shSetup((Vector3){ 0.3f, 0.2f, -1.0f });
    Texture2D white = solidTexture(WHITE);
    CullShadowCtx on = { false, -1, -1 }, off = { true, -1, -1 };
    Image a = shRender(&s, cullShadowCasters, &on, white, false), b = shRender(&s, cullShadowCasters, &off, white, false);
    int diff = cullDiff(a, b), dark = 0;
    for (int y = 0; y < a.height; y++) for (int x = 0; x < a.width; x++) if (rtPixel(b, x, y).r < 100) dark++;
    printf("    shadow pass: %d of %d casters culled (off: %d), %d shadowed pixels, %d differ\n", on.culled, on.count, off.culled, dark, diff);
    RT_CHECK(on.count == 48 && on.culled >= 16 && off.culled == 0, "culled %d of %d (off %d)", on.culled, on.count, off.culled);
    RT_CHECK(dark > 50 && diff == 0, "%d shadowed pixels, %d differ with culling on and off", dark, diff);
    if (diff > 0) { rtSaveImage(a, "cull_shadow_on"); rtSaveImage(b, "cull_shadow_off"); }
    UnloadImage(a); UnloadImage(b);
    UnloadTexture(white);
    shClearScene();
}

#define RBL_CULL_TESTS \
    RT_TEST(test_cull_batches_skip_what_the_camera_cannot_see_and_draw_the_same_picture), \
    RT_TEST(test_cull_shadow_pass_batches_skip_casters_outside_the_light_and_cast_the_same_shadows)
