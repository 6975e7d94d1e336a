// Batched and immediate paths (GPU, headless): a batch grows with one log line, skips bad input
// once and draws what the immediate path draws; parity with raylib's DrawBillboardPro captured from
// rlgl's own batch. Included by gpu_tests.h.

// ---- batch --------------------------------------------------------------------------------------
static void test_batch_grows_with_a_log_line_skips_bad_input_once_and_matches_immediate(void)
{
    Camera3D cam = frontCamera();
    Scene s = sceneLoad((Color){ 200, 150, 100, 255 }, normalTexel(0, 0, 1), false);
    RblLight l = rtPointLight((Vector3){ 1, 1, 3 }, 8.0f);
    RT_CHECK(renderSetLights(&l, 1, (Color){ 20, 20, 20, 255 }), "scene rejected");
    RblBatch batch = RblLoadBatch(2);
    RT_CHECK(RblIsBatchValid(batch), "batch not created");
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    unsigned int seed = 5u;
    RblBillboard set[9];
    for (int i = 0; i < 9; i++)
    {
        set[i] = centredQuad();
        set[i].size = (Vector2){ 0.6f, 0.6f }; set[i].origin = (Vector2){ 0.3f, 0.3f };
        set[i].position = (Vector3){ rtRandomRange(&seed, -1.5f, 1.5f), rtRandomRange(&seed, -1.5f, 1.5f), -0.1f*i };
        set[i].facing = i%4;
    }
    set[4].position.y = NAN;        // skipped
    set[6].rotation = INFINITY;     // skipped, not logged again
    SetTraceLogLevel(LOG_INFO);
    for (int frame = 0; frame < 2; frame++)
    {
        warnings = 0;
        BeginTextureMode(rt);
        ClearBackground(BLACK);
        BeginMode3D(cam);
        RblBeginBatch(&batch, cam);
        int added = 0;
        for (int i = 0; i < 9; i++) added += RblBatchAdd(&batch, s.material, &set[i]);
        RT_CHECK(added == 7 && batch.count == 7 && batch.skipped == 2, "frame %d: added %d count %d skipped %d", frame, added, batch.count, batch.skipped);
        RblEndBatch(&batch);
        EndMode3D();
        EndTextureMode();
        // frame 0: one "grown" info line per doubling (2 -> 4 -> 8) plus one skip warning; frame 1: the skip warning only
        RT_CHECK(warnings == ((frame == 0)? 3 : 1), "frame %d: %d RBL log lines (%s)", frame, warnings, lastWarning);
        RT_CHECK(batch.capacity == 8, "capacity %d", batch.capacity);
    }
    SetTraceLogLevel(LOG_WARNING);
    Image batched = rtReadTarget(rt);
    // The same billboards drawn one by one through the immediate path give the same pixels
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(cam);
    for (int i = 0; i < 9; i++) RblDrawBillboard(cam, s.material, set[i]);
    EndMode3D();
    EndTextureMode();
    Image immediate = rtReadTarget(rt);
    int differing = 0, lit = 0;
    for (int y = 0; y < TARGET; y++)
    for (int x = 0; x < TARGET; x++)
    {
        Color a = rtPixel(batched, x, y), b = rtPixel(immediate, x, y);
        if (a.r != b.r || a.g != b.g || a.b != b.b) differing++;
        if (a.r > 0) lit++;
    }
    RT_CHECK(lit > 200, "batched image nearly empty (%d lit pixels)", lit);
    RT_CHECK(differing == 0, "%d pixels differ between batched and immediate", differing);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(batched, "batched"); rtSaveImage(immediate, "immediate"); }
    UnloadImage(batched); UnloadImage(immediate);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    RT_CHECK(!RblIsBatchValid(batch) && batch.state == NULL, "unload left state behind");
    sceneUnload(s);
}

// A Material is a value: a copy that shares the shader and maps but holds other params (here the
// alpha cutoff) starts its own run and draws with its own values, as raylib's DrawMesh would; the
// batch draws what the immediate path draws billboard by billboard
static Image batchParamsFrame(RenderTexture2D rt, Camera3D cam, RblBatch *batch, const Material *mats, const RblBillboard *set, int n)
{
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(cam);
    if (batch != NULL)
    {
        RblBeginBatch(batch, cam);
        for (int i = 0; i < n; i++) RblBatchAdd(batch, mats[i], &set[i]);
        RblEndBatch(batch);
    }
    else for (int i = 0; i < n; i++) RblDrawBillboard(cam, mats[i], set[i]);
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(rt);
}

static void test_batch_material_copies_with_other_params_draw_with_their_own(void)
{
    Camera3D cam = frontCamera();
    Scene s = sceneLoad((Color){ 200, 150, 100, 128 }, normalTexel(0, 0, 1), false);       // every texel half transparent
    RblLight l = rtPointLight((Vector3){ 1, 1, 3 }, 8.0f);
    RT_CHECK(renderSetLights(&l, 1, (Color){ 20, 20, 20, 255 }), "scene rejected");
    Material keep = s.material, cut = s.material;        // the same shader and maps array
    keep.params[RBL_PARAM_ALPHA_CUTOFF] = 0.25f;         // keeps the texels (alpha 0.5)
    cut.params[RBL_PARAM_ALPHA_CUTOFF] = 0.75f;          // discards them
    RblBillboard set[6];
    Material mats[6], allKeep[6];
    for (int i = 0; i < 6; i++)
    {
        set[i] = centredQuad();
        set[i].size = (Vector2){ 0.8f, 0.8f }; set[i].origin = (Vector2){ 0.4f, 0.4f };
        set[i].position = (Vector3){ -1.5f + 0.6f*(float)i, 0.0f, 0.0f };
        mats[i] = (i < 3)? keep : cut;
        allKeep[i] = keep;
    }
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    RblBatch batch = RblLoadBatch(8);
    Image batched = batchParamsFrame(rt, cam, &batch, mats, set, 6);
    int runs = (batch.state != NULL)? batch.state->runCount : -1;
    Image immediate = batchParamsFrame(rt, cam, NULL, mats, set, 6);
    Image kept = batchParamsFrame(rt, cam, NULL, allKeep, set, 6);
    int differing = 0, litBatched = 0, litKept = 0;
    for (int y = 0; y < TARGET; y++)
    for (int x = 0; x < TARGET; x++)
    {
        Color a = rtPixel(batched, x, y), b = rtPixel(immediate, x, y), k = rtPixel(kept, x, y);
        differing += (a.r != b.r) || (a.g != b.g) || (a.b != b.b);
        litBatched += a.r > 0; litKept += k.r > 0;
    }
    printf("    2 materials sharing shader and maps, alpha cutoff 0.25 / 0.75: %d runs, %d lit pixels (all kept: %d), %d differ from the immediate path\n",
           runs, litBatched, litKept, differing);
    RT_CHECK(runs == 2, "%d runs for two material values (expected 2)", runs);
    RT_CHECK((litBatched > 200) && (litBatched < litKept - 200), "lit pixels %d, with every billboard kept %d (test setup: the cutoff must cut)", litBatched, litKept);
    RT_CHECK(differing == 0, "%d pixels differ between batched and immediate", differing);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(batched, "batched"); rtSaveImage(immediate, "immediate"); }
    UnloadImage(batched); UnloadImage(immediate); UnloadImage(kept);
    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    sceneUnload(s);
}

// ---- parity with raylib ---------------------------------------------------------------------------
// raylib's own DrawBillboardPro output, captured from an rlgl batch before it is drawn
static void test_parity_camera_plane_positions_and_uvs_equal_raylib_draw_billboard_pro(void)
{
    rlRenderBatch capture = rlLoadRenderBatch(1, 4096);
    RenderTexture2D scratch = LoadRenderTexture(8, 8);
    Texture2D tex = { rlGetTextureIdDefault(), 256, 128, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8 };
    unsigned int seed = 2024u;
    double worstPos = 0.0, worstUv = 0.0;
    int compared = 0;
    for (int camIndex = 0; camIndex < 8; camIndex++)
    {
        Camera3D cam = frontCamera();
        cam.position = (Vector3){ rtRandomRange(&seed, -10, 10), rtRandomRange(&seed, -5, 8), rtRandomRange(&seed, 5, 15) };
        cam.target = (Vector3){ rtRandomRange(&seed, -2, 2), rtRandomRange(&seed, -2, 2), rtRandomRange(&seed, -2, 2) };
        RblCameraFrame view = RblGetCameraFrame(cam);
        BeginTextureMode(scratch);
        rlSetRenderBatchActive(&capture);
        RblBillboard set[64];
        for (int i = 0; i < 64; i++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.position = (Vector3){ rtRandomRange(&seed, -5, 5), rtRandomRange(&seed, -5, 5), rtRandomRange(&seed, -5, 5) };
            b.size = (Vector2){ rtRandomRange(&seed, 0.1f, 3), rtRandomRange(&seed, 0.1f, 3) };
            b.origin = (Vector2){ rtRandomRange(&seed, 0, 1.5f), rtRandomRange(&seed, 0, 1.5f) };
            b.rotation = (i%2)? rtRandomRange(&seed, -180, 180) : 0.0f;
            b.source = (Rectangle){ floorf(rtRandomRange(&seed, 0, 200)), floorf(rtRandomRange(&seed, 0, 100)), floorf(rtRandomRange(&seed, 1, 56)), floorf(rtRandomRange(&seed, 1, 28)) };
            b.up = (i%3 == 0)? (Vector3){ 0, 1, 0 } : (Vector3){ rtRandomRange(&seed, -0.3f, 0.3f), 1.0f, rtRandomRange(&seed, -0.3f, 0.3f) };
            set[i] = b;
            DrawBillboardPro(cam, tex, b.source, b.position, b.up, b.size, b.origin, b.rotation, WHITE);
        }
        const float *rv = capture.vertexBuffer[capture.currentBuffer].vertices;
        const float *rt = capture.vertexBuffer[capture.currentBuffer].texcoords;
        for (int i = 0; i < 64; i++)
        {
            RblVertex q[4];
            RT_CHECK(RblBillboardVertices(&view, tex.width, tex.height, &set[i], q), "skipped");
            double scale = 1.0 + dLen(d3f(set[i].position)) + set[i].size.x + set[i].size.y;
            for (int k = 0; k < 4; k++)
            {
                const float *p = rv + (i*4 + k)*3, *uv = rt + (i*4 + k)*2;
                double e = v3dist(q[k].position, d3(p[0], p[1], p[2]))/scale;
                double eu = fmax(fabs(q[k].texcoord[0] - uv[0]), fabs(q[k].texcoord[1] - uv[1]));
                if (e > worstPos) worstPos = e;
                if (eu > worstUv) worstUv = eu;
            }
            compared++;
        }
        rlSetRenderBatchActive(NULL);      // draws the captured quads (into the scratch target) and resets
        EndTextureMode();
    }
    RT_CHECK(compared == 512, "compared %d billboards", compared);
    RT_CHECK(worstPos < 1e-6, "worst relative position difference from DrawBillboardPro %.3g", worstPos);
    RT_CHECK(worstUv == 0.0, "worst uv difference from DrawBillboardPro %.3g", worstUv);
    printf("    parity: worst relative corner difference %.2e, worst uv difference %.2e over %d billboards\n", worstPos, worstUv, compared);
    rlUnloadRenderBatch(capture);
    UnloadRenderTexture(scratch);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_BATCH_TESTS \
    RT_TEST(test_batch_grows_with_a_log_line_skips_bad_input_once_and_matches_immediate), \
    RT_TEST(test_batch_material_copies_with_other_params_draw_with_their_own), \
    RT_TEST(test_parity_camera_plane_positions_and_uvs_equal_raylib_draw_billboard_pro)
