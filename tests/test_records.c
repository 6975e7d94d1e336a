// The batch's compact stream (GPU, headless): where the context has GLSL 3 and the header's programs
// draw every run, a batch uploads each billboard as its record (the RblBillboard) and the instanced
// vertex stage expands it (lit_instanced.vs.glsl RBL_BATCH_RECORD). Each case draws the same billboards twice, from records and from
// vertices (the batch held to vertices), and compares the pixels: every facing, both mirrors, turned
// and rotated frames, flat, sphere- and cylinder-rounded, lit with a normal map; cast into a shadow
// map; in a G-buffer; sorted and blended; and a batch that turns to vertices part-way (a user's
// shader after records). The vertices are rbl__expandQuad's (the reference every other test checks).
// Included by gpu_tests.h.

#define REC_RT 256

static Image recNoise(unsigned int seed, bool normals)
{
    Image img = GenImageColor(16, 16, BLACK);
    Color *px = (Color *)img.data;
    for (int i = 0; i < 256; i++)
    {
        unsigned int r = rtRandom(&seed);
        if (!normals) { px[i] = (Color){ (unsigned char)(60 + (r & 127)), (unsigned char)(60 + ((r >> 8) & 127)), (unsigned char)(60 + ((r >> 16) & 127)), 255 }; continue; }
        double nx = ((r & 255) - 127.5)/400.0, ny = (((r >> 8) & 255) - 127.5)/400.0, nz = sqrt(1.0 - nx*nx - ny*ny);
        px[i] = normalTexel((float)nx, (float)ny, (float)nz);
    }
    return img;
}

// The case set: 4 facings x 4 mirrors x turned or not x rotated frame or not x flat, sphere, cylinder
#define REC_SET 192
static void recSet(RblBillboard *set)
{
    for (int k = 0; k < REC_SET; k++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.facing = k%4;
        b.size = (Vector2){ ((k/4) & 1)? -0.34f : 0.34f, ((k/4) & 2)? -0.3f : 0.3f };
        b.origin = (Vector2){ 0.17f, 0.1f };
        b.rotation = ((k/16) & 1)? 33.0f : 0.0f;
        b.source = (Rectangle){ 2.0f, 3.0f, 11.0f, 9.0f };
        if ((k/32) & 1) b.flags |= RBL_FRAME_ROTATED;
        int r = (k/64)%3;
        b.roundness = (r > 0)? 0.6f : 0.0f;
        if (r == 2) b.flags |= RBL_ROUND_CYLINDER;
        b.axis = (Vector3){ 0.2f, 1.0f, 0.1f };
        b.up = (Vector3){ 0.1f, 1.0f, 0.3f };
        b.tint = ((k % 5) == 0)? (Color){ 255, 200, 180, 255 } : BLANK;
        b.position = (Vector3){ -2.1f + 0.3f*(float)(k%16), -1.7f + 0.3f*(float)(k/16), 0.05f*(float)(k%3) };
        set[k] = b;
    }
}

typedef struct RecWorst { int worst, differ, covered, records; } RecWorst;

// Whether batches of records write them into the mapped GPU buffer here (GL 3.3, ES 3; not WebGL)
static bool recMaps(void)
{
#if defined(RBL_NO_MAPPED_BATCH) || defined(__EMSCRIPTEN__)
    return false;
#else
    return rtGlsl3();
#endif
}

static void recCompare(Image a, Image b, RecWorst *w)
{
    for (int i = 0; i < a.width*a.height; i++)
    {
        Color p = ((const Color *)a.data)[i], q = ((const Color *)b.data)[i];
        int d = abs(p.r - q.r);
        if (abs(p.g - q.g) > d) d = abs(p.g - q.g);
        if (abs(p.b - q.b) > d) d = abs(p.b - q.b);
        if (abs(p.a - q.a) > d) d = abs(p.a - q.a);
        w->covered += (q.r | q.g | q.b) != 0;
        w->differ += d > 1;
        if (d > w->worst) w->worst = d;
    }
}

// Draws set through batch (held to vertices or not) with materials m[k % mats] into rt; whether the
// batch held records when it ended
static bool recDraw(RblBatch *batch, bool vertices, Camera3D cam, const Material *m, int mats, const RblBillboard *set, int n, int sort)
{
    rbl__BatchState *st = rbl__batchState(batch);
    if (st == NULL) return false;
    st->vertexOnly = vertices;
    batch->sort = sort;
    RblBeginBatch(batch, cam);
    for (int k = 0; k < n; k++) RblBatchAdd(batch, m[(k/7) % mats], &set[k]);
    bool records = st->records;
    RblEndBatch(batch);
    st->vertexOnly = false;
    return records;
}

static Image recFrame(RenderTexture2D rt, RblBatch *batch, bool vertices, Camera3D cam, const Material *m, int mats, const RblBillboard *set, int n, int sort, bool *records)
{
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(cam);
    *records = recDraw(batch, vertices, cam, m, mats, set, n, sort);
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(rt);
}

static void test_batch_records_draw_what_vertices_draw_lit_mirrored_turned_and_rounded(void)
{
    Camera3D cam = frontCamera();
    RblLight lights[2] = { litDirectional((Vector3){ -0.4f, -0.5f, -0.8f }, 0.9f), rtPointLight((Vector3){ 0.8f, 0.6f, 1.5f }, 3.0f) };
    RT_CHECK(renderSetLights(lights, 2, (Color){ 30, 30, 40, 255 }), "scene rejected");
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 2; desc.shading.lightFeatures = RblGetLightFeatures(lights, 2); desc.material.normalEncoding = RBL_NORMAL_RGB;
    Shader lit = RblLoadLitShader(desc);
    Image ai = recNoise(11u, false), ni = recNoise(12u, true);
    Texture2D albedo = LoadTextureFromImage(ai), normal = LoadTextureFromImage(ni);
    UnloadImage(ai); UnloadImage(ni);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = normal;
    static RblBillboard set[REC_SET];
    recSet(set);
    RblBatch batch = RblLoadBatch(REC_SET);
    RenderTexture2D rt = LoadRenderTexture(REC_RT, REC_RT);
    bool rec[2] = { false, false };
    Image a = recFrame(rt, &batch, false, cam, &m, 1, set, REC_SET, RBL_SORT_NONE, &rec[0]);
    Image b = recFrame(rt, &batch, true, cam, &m, 1, set, REC_SET, RBL_SORT_NONE, &rec[1]);
    RecWorst w = { 0, 0, 0, 0 };
    recCompare(a, b, &w);
    printf("    %d billboards: from %s, worst %d/255 from vertices, %d of %d covered pixels differ by more than 1\n", REC_SET, rec[0]? "records" : "vertices", w.worst, w.differ, w.covered);
    RT_CHECK(rec[0] == rtGlsl3() && !rec[1], "records %s on a GLSL %s context (held to vertices: %s)", rec[0]? "used" : "not used", rtGlsl3()? "3" : "1", rec[1]? "records" : "vertices");
    RT_CHECK(w.covered > REC_RT*REC_RT/4, "only %d pixels covered (test setup)", w.covered);
    RT_CHECK(w.worst <= 1, "records vs vertices: worst %d/255, %d pixels beyond 1/255", w.worst, w.differ);
    if ((rtFailuresInCurrentTest() > 0) || (getenv("RBL_TEST_LOOK") != NULL)) { rtSaveImage(a, "records"); rtSaveImage(b, "vertices"); }
    UnloadImage(a); UnloadImage(b);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    MemFree(m.maps);
    UnloadTexture(albedo); UnloadTexture(normal);
    RblUnloadLitShader(&lit);
}

// Records in the other places a batch draws: cast into a shadow map (the floor's shadows compared),
// in a G-buffer (resolved), sorted back to front and blended across two materials, and a batch that
// turns to vertices when a raylib default material follows records (what it drew compared whole)
static void test_batch_records_cast_fill_the_gbuffer_sort_and_turn_to_vertices_like_vertices(void)
{
    static RblBillboard set[REC_SET];
    recSet(set);
    RblBatch batch = RblLoadBatch(REC_SET);
    RenderTexture2D rt = LoadRenderTexture(REC_RT, REC_RT);
    Camera3D cam = frontCamera();
    RblLight sun = litDirectional((Vector3){ -0.4f, -1.0f, -0.3f }, 1.0f);
    Image ai = recNoise(21u, false);
    Texture2D albedo = LoadTextureFromImage(ai), white = solidTexture(WHITE);
    UnloadImage(ai);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.shading.shadowMaps = 1;
    Shader receiver = RblLoadLitShader(desc);
    desc.shading.shadowMaps = 0;
    Shader lit = RblLoadLitShader(desc);
    desc.deferred = true;
    Shader geo = (rbl__glsl() >= 300)? RblLoadLitShader(desc) : (Shader){ 0 };
    Material m[2] = { LoadMaterialDefault(), LoadMaterialDefault() };
    m[0].shader = lit; m[0].maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    m[1].shader = lit; m[1].maps[MATERIAL_MAP_ALBEDO].texture = white; m[1].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 120, 200, 255, 255 };
    const char *names[4] = { "shadow casters", "G-buffer", "sorted, blended", "turned to vertices" }, *tags[4][2] = {
        { "casters-records", "casters-vertices" }, { "gbuffer-records", "gbuffer-vertices" }, { "sorted-records", "sorted-vertices" }, { "mixed-records", "mixed-vertices" } };
    for (int c = 0; c < 4; c++)
    {
        if ((c == 1) && (geo.id == 0)) continue;         // G-buffers need GLSL 3
        Image img[2];
        bool rec[2] = { false, false };
        for (int v = 0; v < 2; v++)
        {
            if (c == 0)
            {
                // Cards 1 above the floor seen from the top; the floor drawn through the immediate path
                static RblBillboard cards[REC_SET];
                for (int k = 0; k < REC_SET; k++) { cards[k] = set[k]; cards[k].position = (Vector3){ set[k].position.x*1.5f, 1.0f + 0.1f*(float)(k%4), set[k].position.y*1.5f }; }
                RblShadowDesc sd;
                memset(&sd, 0, sizeof(sd));
                sd.size = 256;
                RblShadowMap map = RblLoadShadowMap(sd);
                RblScene scene;
                memset(&scene, 0, sizeof(scene));
                scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 30, 30, 30, 255 };
                if (RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.5f, 0.0f }, 5.0f))
                {
                    rec[v] = recDraw(&batch, v == 1, ssTopCamera(), m, 1, cards, REC_SET, RBL_SORT_NONE);
                    RblEndShadowMap(&map);
                }
                scene.shadowMaps = &map; scene.shadowMapCount = 1;
                RT_CHECK(RblSetScene(&scene), "scene rejected");
                Material floor = m[0];
                floor.shader = receiver;
                BeginTextureMode(rt);
                ClearBackground(BLACK);
                BeginMode3D(ssTopCamera());
                RblDrawBillboard(ssTopCamera(), floor, ssFloor());
                EndMode3D();
                EndTextureMode();
                img[v] = rtReadTarget(rt);
                RblUnloadShadowMap(&map);
                shClearScene();
            }
            else if (c == 1)
            {
                RT_CHECK(renderSetLights(&sun, 1, (Color){ 30, 30, 30, 255 }), "scene rejected");
                RblGBufferDesc gd;
                memset(&gd, 0, sizeof(gd));
                gd.width = REC_RT; gd.height = REC_RT; gd.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
                RblGBuffer g = RblLoadGBuffer(gd);
                Material gm = m[0];
                gm.shader = geo;
                if (RblBeginGBuffer(&g, cam))
                {
                    rec[v] = recDraw(&batch, v == 1, cam, &gm, 1, set, REC_SET, RBL_SORT_NONE);
                    RblEndGBuffer(&g);
                    RblDrawDeferredLights(&g);
                }
                BeginTextureMode(rt);
                ClearBackground(BLANK);
                RblResolveGBuffer(&g);
                EndTextureMode();
                img[v] = rtReadTarget(rt);
                RblUnloadGBuffer(&g);
            }
            else
            {
                RT_CHECK(renderSetLights(&sun, 1, (Color){ 30, 30, 30, 255 }), "scene rejected");
                static RblBillboard see[REC_SET];
                Material mats[2] = { m[0], m[1] };
                if (c == 3) mats[1] = LoadMaterialDefault();     // raylib's default shader: the batch turns to vertices
                for (int k = 0; k < REC_SET; k++) { see[k] = set[k]; see[k].tint = (Color){ 255, 255, 255, (unsigned char)((c == 2)? 140 : 255) }; }
                img[v] = recFrame(rt, &batch, v == 1, cam, mats, 2, see, REC_SET, (c == 2)? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE, &rec[v]);
                if (c == 3) MemFree(mats[1].maps);
            }
        }
        RecWorst w = { 0, 0, 0, 0 };
        recCompare(img[0], img[1], &w);
        bool want = rtGlsl3() && (c != 3);
        printf("    %-18s: batch %s, worst %d/255 from vertices, %d of %d covered pixels differ by more than 1\n", names[c], rec[0]? "records" : "vertices", w.worst, w.differ, w.covered);
        RT_CHECK(rec[0] == want && !rec[1], "%s: the batch ended with %s (expected %s)", names[c], rec[0]? "records" : "vertices", want? "records" : "vertices");
        RT_CHECK(w.covered > REC_RT*REC_RT/8, "%s: only %d pixels covered (test setup)", names[c], w.covered);
        int shadowed = 0;
        for (int k = 0; (c == 0) && (k < REC_RT*REC_RT); k++) shadowed += luminance(((const Color *)img[0].data)[k]) < 3*50;
        RT_CHECK((c != 0) || (shadowed > REC_RT*REC_RT/20), "the casters shadow only %d floor pixels (test setup)", shadowed);
        RT_CHECK(w.worst <= 1, "%s: records vs vertices worst %d/255, %d pixels beyond 1/255", names[c], w.worst, w.differ);
        if ((rtFailuresInCurrentTest() > 0) || (getenv("RBL_TEST_LOOK") != NULL)) { rtSaveImage(img[0], tags[c][0]); rtSaveImage(img[1], tags[c][1]); }
        UnloadImage(img[0]); UnloadImage(img[1]);
    }
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    MemFree(m[0].maps); MemFree(m[1].maps);
    UnloadTexture(albedo); UnloadTexture(white);
    RblUnloadLitShader(&lit); RblUnloadLitShader(&receiver);
    if (geo.id != 0) RblUnloadLitShader(&geo);
}

// A shadow receiver's batch of records leaves the identity stream unwritten (the record stage hashes
// each billboard): turned to vertices part-way (a cross-fade added), every earlier billboard gets
// its identity (rbl__casterId of its pivot, size and origin) on all four vertices; on GLSL 1 the
// stream is written as billboards arrive
static void test_batch_records_turned_to_vertices_carry_their_caster_identities(void)
{
    static RblBillboard set[REC_SET];
    recSet(set);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.shading.shadowMaps = 1;
    Shader receiver = RblLoadLitShader(desc);
    Texture2D white = solidTexture(WHITE);
    Material m = LoadMaterialDefault();
    m.shader = receiver;
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    RblBatch batch = RblLoadBatch(REC_SET + 1);
    batch.noCull = true;
    Camera3D cam = frontCamera();
    RenderTexture2D rt = LoadRenderTexture(64, 64);
    BeginTextureMode(rt);
    BeginMode3D(cam);
    RblBeginBatch(&batch, cam);
    for (int k = 0; k < REC_SET; k++) RblBatchAdd(&batch, m, &set[k]);
    rbl__BatchState *st = rbl__batchState(&batch);
    bool heldRecords = (st != NULL) && st->records && st->identified;
    RblFade fade;
    memset(&fade, 0, sizeof(fade));
    fade.weight = 0.5f;
    RT_CHECK(RblBatchAddFade(&batch, m, &set[0], &fade), "the cross-fade billboard was refused");
    int wrong = 0, checked = 0;
    for (int i = 0; (st != NULL) && st->identified && !st->records && (i < REC_SET); i++)
    {
        unsigned int id = rbl__casterId(set[i].position, set[i].size, set[i].origin);
        for (int v = 0; v < 4; v++, checked++)
        {
            const unsigned char *o = st->ids + (size_t)i*RBL__ID_BYTES + 4*v;
            wrong += (o[0] != (id >> 8)) || (o[1] != (id & 255u)) || (o[2] != 0) || (o[3] != 0);
        }
    }
    RblEndBatch(&batch);
    EndMode3D();
    EndTextureMode();
    printf("    receiver batch: %s before the cross-fade, then vertices; %d of %d vertex identities wrong\n", heldRecords? "records" : "vertices", wrong, checked);
    RT_CHECK(heldRecords == rtGlsl3(), "the receiver batch held %s before the cross-fade", heldRecords? "records" : "vertices");
    RT_CHECK((checked == 4*REC_SET) && (wrong == 0), "%d of %d identities wrong after turning to vertices", wrong, checked);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    MemFree(m.maps);
    UnloadTexture(white);
    RblUnloadLitShader(&receiver);
}

static void recHardSet(RblBillboard *set);

// One frame of set through batch into rt (cleared), billboard fadeAt (if >= 0) added with fade;
// whether records were in the mapped buffer when the batch ended, and sort set after RblBeginBatch
static Image recMappedFrame(RenderTexture2D rt, RblBatch *batch, Camera3D cam, const Material *m, const RblBillboard *set, int n, int lateSort, int fadeAt, const RblFade *fade, bool *mapped)
{
    rbl__BatchState *st = rbl__batchState(batch);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(cam);
    RblBeginBatch(batch, cam);
    for (int k = 0; k < n; k++)
    {
        if (k == fadeAt) RblBatchAddFade(batch, *m, &set[k], fade);
        else RblBatchAdd(batch, *m, &set[k]);
    }
    batch->sort = lateSort;
    *mapped = (st != NULL) && (st->mapped != NULL);
    RblEndBatch(batch);
    batch->sort = RBL_SORT_NONE;
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(rt);
}

// Where the context maps buffers, a batch of records drawn in submission order writes each record
// straight into its GPU buffer (nothing uploaded at RblEndBatch): read back after the draw, every
// record is the billboard as the record stage reads it (flags masked to the rotated and cylinder
// bits, FIXED and AXIS directions tamed), bit for bit. A step that must read them on the CPU reads
// them back first, and draws exactly what a batch that kept them on the CPU draws: growing past its
// capacity, a sort mode set after RblBeginBatch, a cross-fade that turns the batch to vertices. A
// read-back while the batch is open rests mapping for the next RBL__MAP_REST batches; a batch
// unloaded while mapped leaves GL without an error
static void test_batch_records_mapped_read_back_bit_for_bit_and_draw_as_kept_ones(void)
{
    static RblBillboard set[REC_SET];
    recHardSet(set);
    Shader lit = RblLoadLitShader((RblLitShaderDesc){ .maxLights = 1 });
    Image ai = recNoise(31u, false);
    Texture2D albedo = LoadTextureFromImage(ai);
    UnloadImage(ai);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    Camera3D cam = frontCamera();
    RenderTexture2D rt = LoadRenderTexture(REC_RT, REC_RT);
    const bool maps = recMaps();

    // Bit for bit, after the draw
    RblBatch batch = RblLoadBatch(REC_SET);
    batch.noCull = true;                    // every billboard takes its slot, in order
    rbl__BatchState *st = rbl__batchState(&batch);
    bool mapped = false;
    Image kept = recMappedFrame(rt, &batch, cam, &m, set, REC_SET, RBL_SORT_NONE, -1, NULL, &mapped);
    bool onGpu = st->onGpu, read = rbl__recordsToCpu(st);
    int differ = 0;
    for (int i = 0; read && (i < st->count); i++)
    {
        rbl__BatchRecord e = set[i];
        e.flags &= RBL_FRAME_ROTATED | RBL_ROUND_CYLINDER;
        if (e.facing != RBL_FACING_CAMERA_PLANE) { e.up = rbl__tame(set[i].up); e.axis = rbl__tame(set[i].axis); }
        differ += memcmp(&e, (const rbl__BatchRecord *)(const void *)st->vertices + i, sizeof(e)) != 0;
    }
    printf("    %d records %s, %d differ from the billboards as the stage reads them\n", st->count, onGpu? "written into the mapped buffer, read back" : "kept on the CPU", differ);
    RT_CHECK((mapped == maps) && (onGpu == maps), "records in the mapped buffer: %s while open, %s after the draw (expected: %s)", mapped? "yes" : "no", onGpu? "yes" : "no", maps? "yes" : "no");
    RT_CHECK(read && (st->count == REC_SET) && (differ == 0), "%d of %d records read back differ (read back: %s)", differ, st->count, read? "yes" : "no");
    UnloadImage(kept);

    // The references: the same frames with mapping rested (records kept on the CPU)
    RblFade fade;
    memset(&fade, 0, sizeof(fade));
    fade.source = (Rectangle){ 4.0f, 1.0f, 9.0f, 11.0f }; fade.weight = 0.5f;
    const char *names[3] = { "grown past its capacity", "sorted after RblBeginBatch", "turned to vertices by a cross-fade" };
    for (int c = 0; c < 3; c++)
    {
        RblBatch a = RblLoadBatch((c == 0)? 8 : REC_SET), b = RblLoadBatch(REC_SET);
        a.noCull = b.noCull = true;
        rbl__BatchState *sa = rbl__batchState(&a), *sb = rbl__batchState(&b);
        sb->mapRest = 1;
        int sort = (c == 1)? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE, fadeAt = (c == 2)? REC_SET/2 : -1;
        bool mappedA = false, mappedB = false;
        Image ia = recMappedFrame(rt, &a, cam, &m, set, REC_SET, sort, fadeAt, &fade, &mappedA);
        Image ib = recMappedFrame(rt, &b, cam, &m, set, REC_SET, sort, fadeAt, &fade, &mappedB);
        RecWorst w = { 0, 0, 0, 0 };
        recCompare(ia, ib, &w);
        // Mapped at the first record; still open at the end only where nothing read them back before
        const bool openAtEnd = maps && (c == 1), rested = maps && (c != 1);
        printf("    %-34s: %s, worst %d/255 from the kept batch's (%d pixels covered), mapping %s\n", names[c], maps? "read back" : "kept on the CPU", w.worst, w.covered,
               (sa->mapRest == RBL__MAP_REST)? "rested" : "not rested");
        RT_CHECK((mappedA == openAtEnd) && !mappedB, "%s: mapped at the end %s (expected %s), reference %s", names[c], mappedA? "yes" : "no", openAtEnd? "yes" : "no", mappedB? "mapped" : "kept");
        RT_CHECK((sa->count == REC_SET) && (sa->mapRest == (rested? RBL__MAP_REST : 0)), "%s: %d billboards drawn, mapping rests %d batches", names[c], sa->count, sa->mapRest);
        RT_CHECK(w.covered > REC_RT*REC_RT/16, "%s: only %d pixels covered (test setup)", names[c], w.covered);
        RT_CHECK(w.worst == 0, "%s: %d pixels differ from the kept batch's (worst %d/255)", names[c], w.differ, w.worst);
        if ((rtFailuresInCurrentTest() > 0) || (getenv("RBL_TEST_LOOK") != NULL)) { rtSaveImage(ia, "read-back"); rtSaveImage(ib, "kept"); }
        UnloadImage(ia); UnloadImage(ib);
        if (c == 0)
        {
            // Resting: the next RBL__MAP_REST batches keep their records on the CPU, then mapping resumes
            int mappedFrames = 0;
            for (int f = 0; f <= RBL__MAP_REST; f++)
            {
                BeginTextureMode(rt);
                BeginMode3D(cam);
                RblBeginBatch(&a, cam);
                RblBatchAdd(&a, m, &set[0]);
                mappedFrames += (sa->mapped != NULL)? ((f == RBL__MAP_REST)? 1 : 1000) : 0;
                RblEndBatch(&a);
                EndMode3D();
                EndTextureMode();
            }
            RT_CHECK(mappedFrames == (maps? 1 : 0), "after a read-back: mapped in %d of %d batches' rest, in the next %s", mappedFrames/1000, RBL__MAP_REST, (mappedFrames % 1000)? "yes" : "no");
        }
        RblUnloadBatch(&a); RblUnloadBatch(&b);
    }

    // Unloaded while mapped, then a batch drawn as before
    unsigned int (*getError)(void) = NULL;
    void *e = rtGlProc("glGetError");
    memcpy(&getError, &e, sizeof(e));
    for (int k = 0; (getError != NULL) && (k < 16) && (getError() != 0u); k++) { }     // errors of earlier steps
    RblBatch open = RblLoadBatch(16);
    rbl__BatchState *so = rbl__batchState(&open);
    BeginTextureMode(rt);
    BeginMode3D(cam);
    RblBeginBatch(&open, cam);
    for (int k = 0; k < 5; k++) RblBatchAdd(&open, m, &set[k]);
    bool openMapped = (so != NULL) && (so->mapped != NULL);
    RblUnloadBatch(&open);
    EndMode3D();
    EndTextureMode();
    unsigned int error = (getError != NULL)? getError() : 0u;
    Image again = recMappedFrame(rt, &batch, cam, &m, set, REC_SET, RBL_SORT_NONE, -1, NULL, &mapped);
    st->mapRest = 1;
    Image cpu = recMappedFrame(rt, &batch, cam, &m, set, REC_SET, RBL_SORT_NONE, -1, NULL, &mapped);
    RecWorst w = { 0, 0, 0, 0 };
    recCompare(again, cpu, &w);
    RT_CHECK((openMapped == maps) && (error == 0u), "a batch unloaded while %s: GL error 0x%x", openMapped? "mapped" : "not mapped", error);
    RT_CHECK((w.worst == 0) && (w.covered > REC_RT*REC_RT/16), "after it, a mapped batch differs from a kept one in %d pixels (worst %d/255, %d covered)", w.differ, w.worst, w.covered);
    UnloadImage(again); UnloadImage(cpu);

    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    MemFree(m.maps);
    UnloadTexture(albedo);
    RblUnloadLitShader(&lit);
}

// Billboards of the stage's hard inputs added to the set: FIXED and AXIS up and axis far beyond
// what float squares (tamed as the CPU tames them), flag bits no path reads, far pivots
static void recHardSet(RblBillboard *set)
{
    recSet(set);
    for (int k = 0; k < REC_SET; k += 7) set[k].position = (Vector3){ 3000.5f + (float)k, -1200.25f, -40000.0f };    // far: large coordinates
    for (int k = 3; k < REC_SET; k += 5)
    {
        if (set[k].facing != RBL_FACING_CAMERA_PLANE) { set[k].axis = (Vector3){ 2e30f, 1e36f, -3e29f }; set[k].up = (Vector3){ -1e33f, 4e37f, 5e35f }; }
        set[k].flags |= 0x40000000u;
    }
}

// The record stage's capture (tfCaptureRecords with the pass's frame, set by the caller) against the
// CPU's vertices of the same batch (gathered in its pass); the worst position (relative to the
// billboard's extent), uv and normal/tangent difference
typedef struct RecStage { double pos, uv, frame; } RecStage;
static RecStage recStageError(TfGl *gl, GLu prog, const rbl__BatchState *st, const RblBillboard *set, const RblVertex *cpu)
{
    RecStage e = { 0.0, 0.0, 0.0 };
    float *gpu = tfCaptureRecords(gl, prog, st, REC_SET);
    const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
    for (int i = 0; (gpu != NULL) && (i < REC_SET); i++)
    {
        double scale = 1.0 + dLen(d3f(set[i].position)) + fabs(set[i].size.x) + fabs(set[i].size.y) + fabs(set[i].origin.x) + fabs(set[i].origin.y);
        for (int v = 0; v < 6; v++)
        {
            const float *g = gpu + ((size_t)i*6 + v)*TF_FLOATS;
            const RblVertex *c = &cpu[4*i + cornerOf[v]];
            for (int k = 0; k < 3; k++) e.pos = fmax(e.pos, fabs(g[k] - c->position[k])/scale);
            for (int k = 0; k < 2; k++) e.uv = fmax(e.uv, fabs(g[3 + k] - c->texcoord[k]));
            for (int k = 0; k < 3; k++) e.frame = fmax(e.frame, fabs(g[5 + k] - c->normal[k]));
            for (int k = 0; k < 4; k++) e.frame = fmax(e.frame, fabs(g[8 + k] - c->tangent[k]));
        }
    }
    if (gpu == NULL) e.pos = e.uv = e.frame = INFINITY;
    free(gpu);
    return e;
}

// The record vertex stage's own output (transform feedback): per corner the position, texture
// coordinate, normal and tangent the vertex path writes (rbl__expandQuad: RblBillboardVertices in a
// colour pass, the batch's own expansion in a shadow pass), for the 192-billboard set with far ones,
// huge FIXED/AXIS directions and stray flag bits: in a colour pass, and cast by a directional light
// (light-facing, and facing the camera) and an omni light (light-facing: its CAMERA_PLANE cards turn
// to CAMERA_POSITION; facing the camera) with AXIS tilts
static void test_batch_records_vertex_stage_emits_the_vertex_paths_corners_normals_and_tangents(void)
{
    TfGl gl;
    if (!tfLoad(&gl)) { RT_CHECK(false, "transform feedback entry points missing"); return; }
    GLu prog = tfRecordProgram(&gl);
    RT_CHECK(prog != 0, "the record vertex stage did not link with transform feedback");
    if (prog == 0) return;
    static RblBillboard set[REC_SET];
    static RblVertex cpu[4*REC_SET];
    recHardSet(set);
    Shader lit = RblLoadLitShader((RblLitShaderDesc){ .maxLights = 1 });
    Texture2D white = solidTexture(WHITE);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    RblBatch batch = RblLoadBatch(REC_SET);
    batch.noCull = true;                    // every billboard takes its slot, in order
    Camera3D cam = frontCamera();
    RenderTexture2D rt = LoadRenderTexture(64, 64);
    BeginTextureMode(rt);
    BeginMode3D(cam);
    bool records = recDraw(&batch, false, cam, &m, 1, set, REC_SET, RBL_SORT_NONE);
    EndMode3D();
    EndTextureMode();
    UnloadRenderTexture(rt);
    rbl__BatchState *st = rbl__batchState(&batch);
    RT_CHECK(records && (st != NULL) && (st->count == REC_SET), "the batch did not end with %d records", REC_SET);
    RT_CHECK((st != NULL) && (st->onGpu == recMaps()), "records %s the GPU buffer (mapping expected: %s)", ((st != NULL) && st->onGpu)? "written into" : "uploaded to", recMaps()? "yes" : "no");
    if (records && (st != NULL) && (st->count == REC_SET))
    {
        RblCameraFrame view = RblGetCameraFrame(cam);
        for (int i = 0; i < REC_SET; i++) RT_CHECK(RblBillboardVertices(&view, 4, 4, &set[i], cpu + 4*i), "billboard %d refused by the vertex path", i);
        RecStage e = recStageError(&gl, prog, st, set, cpu);
        printf("    record stage vs the vertex path (%d billboards, %d far, %d huge directions): position %.2e of the extent, uv %.2e, normal/tangent %.2e\n",
               REC_SET, (REC_SET + 6)/7, (REC_SET + 1)/5, e.pos, e.uv, e.frame);
        RT_CHECK(e.pos < 1e-6 && e.uv < 1e-6 && e.frame < 1e-6, "record stage vs vertex path: position %.3g, uv %.3g, normal/tangent %.3g", e.pos, e.uv, e.frame);
    }

        // Shadow passes: the batch's own CPU expansion and the capture, both in the pass
    // The sun shines from behind the cards the camera faces: light-facing ones turn their fronts to it
    RblLight lights[2] = { litDirectional((Vector3){ 0.3f, -0.5f, 0.8f }, 1.0f), rtPointLight((Vector3){ 0.5f, 2.5f, 1.0f }, 4.0f) };
    const char *names[4] = { "directional, light-facing", "directional, camera-facing", "omni face 2, light-facing", "omni face 4, camera-facing" };
    for (int c = 0; c < 4; c++)
    {
        RblShadowDesc sd;
        memset(&sd, 0, sizeof(sd));
        sd.size = 64; sd.omni = (c >= 2); sd.faceCamera = (c & 1) != 0;
        RblShadowMap map = RblLoadShadowMap(sd);
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = lights; scene.lightCount = 2;
        bool cast = false, held = false;
        RecStage e = { INFINITY, INFINITY, INFINITY };
        if (RblBeginShadowMapPass(&map, &scene, (c >= 2)? 1 : 0, (c >= 2)? 2*(c - 1) : 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 6.0f))
        {
            cast = true;
            RblBeginBatch(&batch, cam);
            for (int k = 0; k < REC_SET; k++) RblBatchAdd(&batch, m, &set[k]);
            RblEndBatch(&batch);
            // After the draw, still in the pass: records the adds wrote into the mapped buffer are read back
            held = st->records && (st->count == REC_SET);
            for (int i = 0; held && (i < REC_SET); i++) rtBatchVertices(st, i, cpu + 4*i);
            if (held) e = recStageError(&gl, prog, st, set, cpu);
            RblEndShadowMap(&map);
        }
        RblUnloadShadowMap(&map);
        RT_CHECK(cast && held, "%s: no shadow pass, or the batch held no %d records", names[c], REC_SET);
        if (!(cast && held)) continue;
        printf("    cast, %-27s: position %.2e of the extent, uv %.2e, normal/tangent %.2e\n", names[c], e.pos, e.uv, e.frame);
        RT_CHECK(e.pos < 1e-6 && e.uv < 1e-6 && e.frame < 1e-6, "%s: record stage vs vertex path: position %.3g, uv %.3g, normal/tangent %.3g", names[c], e.pos, e.uv, e.frame);
    }
    gl.DeleteProgram(prog);
    RblUnloadBatch(&batch);
    MemFree(m.maps);
    UnloadTexture(white);
    RblUnloadLitShader(&lit);
}

// ---- RblBatchAddMany ------------------------------------------------------------------------------
// The case set for a bulk add: stretches of 1-40 billboards sharing a key (facing, up, axis; a new
// key changes one word of it), pivots in and out of the view (culled at every lane of a four),
// CAMERA_PLANE cards with a tilted caller up whose back some pivots see, FIXED cards facing away,
// FIXED directions long enough to be tamed, flag bits the record drops, and bad billboards (each
// checked word NaN, Inf or past its bound, one word of up or axis NaN or Inf, a bad facing, a
// polygon handle no atlas has)
static void manySet(unsigned int seed, RblBillboard *set, int n)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 0.3f, 0.4f }; b.origin = (Vector2){ 0.15f, 0.0f };
    int left = 0;
    for (int k = 0; k < n; k++)
    {
        if (left-- <= 0)
        {
            left = 1 + (int)(rtRandom(&seed)%40u);
            unsigned int change = rtRandom(&seed)%9u;
            if (change == 0) b.facing = (int)(rtRandom(&seed)%4u);
            else if (change < 4) ((float *)&b.up)[change - 1] = (rtRandom(&seed)%3u == 0)? 0.0f : rtRandomRange(&seed, -1.0f, 1.0f);
            else if (change < 7) ((float *)&b.axis)[change - 4] = rtRandomRange(&seed, -1.0f, 1.0f);
            else if (change == 7) { b.facing = RBL_FACING_CAMERA_PLANE; b.up = (Vector3){ 0.0f, 1.0f, (rtRandom(&seed) & 1u)? 1.0f : -1.0f }; b.axis = (Vector3){ 0.0f, 0.0f, 0.0f }; }
            else { b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, -1.0f }; b.up = (Vector3){ 0.0f, (rtRandom(&seed) & 1u)? 3e12f : 1.0f, 0.0f }; }
        }
        RblBillboard c = b;
        bool out = (rtRandom(&seed)%5u) == 0;
        c.position = (Vector3){ rtRandomRange(&seed, -2.0f, 2.0f)*(out? 6.0f : 1.0f), rtRandomRange(&seed, -1.5f, 1.5f), rtRandomRange(&seed, -2.0f, 2.0f) };
        c.size = (Vector2){ rtRandomRange(&seed, -0.5f, 0.5f), rtRandomRange(&seed, -0.5f, 0.5f) };
        c.origin = (Vector2){ rtRandomRange(&seed, -0.3f, 0.3f), rtRandomRange(&seed, -0.3f, 0.3f) };
        c.rotation = rtRandomRange(&seed, -400.0f, 400.0f);
        c.source = (Rectangle){ 1.0f, 2.0f, 5.0f, 6.0f };
        c.tint = (Color){ (unsigned char)rtRandom(&seed), 200, 100, 255 };
        c.roundness = rtRandomRange(&seed, 0.0f, 1.0f);
        c.flags = rtRandom(&seed) & (RBL_FRAME_ROTATED | RBL_ROUND_CYLINDER | 12u | ((rtRandom(&seed)%7u == 0)? 0xff000000u : 0u));
        unsigned int bad = rtRandom(&seed)%400u;
        if (bad < 13)
        {
            // one checked word: 0..11 (pivot, size, origin, rotation, source) or 20 (roundness)
            static const float wrong[4] = { 1e30f, -1e30f, 0.0f, 0.0f };
            unsigned int word = (bad < 12)? bad : 20u, how = rtRandom(&seed)%4u;
            float v = (how < 2)? wrong[how] : (how == 2)? NAN : INFINITY;
            if ((word == 20u) && (how < 2)) v = NAN;          // roundness need only be finite
            memcpy((unsigned char *)&c + 4u*word, &v, sizeof(v));
        }
        else if (bad == 13) c.facing = 9;
        else if (bad == 14) c.flags |= 0x10u;                 // a polygon handle (no atlas loaded here)
        else if (bad < 21)
        {
            // one word of the key (up, axis) NaN or Inf, the rest of it the stretch's
            float v = (rtRandom(&seed) & 1u)? NAN : -INFINITY;
            memcpy((unsigned char *)&c + offsetof(RblBillboard, up) + 4u*(bad - 15u), &v, sizeof(v));
        }
        set[k] = c;
    }
}

// Runs of 8 CAMERA_POSITION billboards (every 200th onward) moved to the edge of the batch's culling
// planes: each one's sphere (rbl__culled's) 1.000002-1.000008 of its radius outside one plane, where
// only the culling sums' rounding slack keeps it
static void manyEdges(const rbl__BatchState *st, unsigned int seed, RblBillboard *set, int n)
{
    if (st->planeCount == 0) return;
    for (int i = 0; i + 8 <= n; i += 200)
    for (int j = i; j < i + 8; j++)
    {
        RblBillboard *b = &set[j];
        b->facing = RBL_FACING_CAMERA_POSITION; b->up = (Vector3){ 0.0f, 0.0f, 0.0f }; b->axis = b->up;
        b->flags = 0u; b->roundness = 0.0f;
        b->position = (Vector3){ 0.0f, 0.0f, 0.0f };
        int k = (int)(rtRandom(&seed)%(unsigned int)st->planeCount);
        float sx = fabsf(b->size.x), sy = fabsf(b->size.y);
        float ax = fabsf(b->origin.x), bx = fabsf(sx - b->origin.x), ay = fabsf(b->origin.y), by = fabsf(sy - b->origin.y);
        float ex = (ax > bx)? ax : bx, ey = (ay > by)? ay : by;
        double r = sqrt((double)(ex*ex + ey*ey))*(1.0 + 2e-6*(double)(1 + (j % 4))), d = (double)st->cull[3][k];
        double move = d + r;                       // n.p' + d = -r after p' = p - move n
        b->position = (Vector3){ (float)(-move*st->cull[0][k]), (float)(-move*st->cull[1][k]), (float)(-move*st->cull[2][k]) };
    }
}

typedef struct ManyRun { int added, count, skipped, culled, warned; } ManyRun;

// One batch of set through RblBatchAdd (chunks NULL) or RblBatchAddMany in chunks of the given sizes
// (cycled), materials m[(k/300) % mats]; left begun
static ManyRun manyAdd(RblBatch *batch, Camera3D cam, const Material *m, int mats, const RblBillboard *set, int n, const int *chunks, int chunkCount)
{
    ManyRun r = { 0, 0, 0, 0, 0 };
    int before = warnings;
    RblBeginBatch(batch, cam);
    for (int k = 0, c = 0; k < n; )
    {
        int size = (chunks == NULL)? 1 : chunks[c++ % chunkCount];
        if (size > n - k) size = n - k;
        if ((k/300) != ((k + size - 1)/300)) size = 300 - k%300;        // one material a call
        const Material mat = m[(k/300) % mats];
        if (chunks == NULL) r.added += RblBatchAdd(batch, mat, &set[k])? 1 : 0;
        else r.added += RblBatchAddMany(batch, mat, &set[k], size);
        k += size;
    }
    r.count = batch->count; r.skipped = batch->skipped; r.culled = batch->culled; r.warned = warnings - before;
    return r;
}

// Slots [0, count) of two batches, their runs and flags: the first difference, or NULL
static const char *manyDiffer(rbl__BatchState *a, rbl__BatchState *b, int *at)
{
    *at = -1;
    if ((a->count != b->count) || (a->culled != b->culled) || (a->skipped != b->skipped)) return "counts";
    if ((a->records != b->records) || (a->backFacing != b->backFacing) || (a->extraSlots != b->extraSlots)) return "records / back-facing / extra slots";
    if (a->runCount != b->runCount) return "run count";
    for (int r = 0; r < a->runCount; r++)
        if ((a->runs[r].first != b->runs[r].first) || (a->runs[r].count != b->runs[r].count) || !rbl__sameMaterial(&a->runs[r].material, &b->runs[r].material)) { *at = r; return "a run"; }
    if (a->records && (!rbl__recordsToCpu(a) || !rbl__recordsToCpu(b))) return "read back";
    size_t slot = a->records? sizeof(rbl__BatchRecord) : 4*sizeof(RblVertex);
    for (int i = 0; i < a->count; i++)
        if (memcmp((const unsigned char *)a->vertices + (size_t)i*slot, (const unsigned char *)b->vertices + (size_t)i*slot, slot) != 0) { *at = i; return "slot bytes"; }
    for (int i = 0; i < a->count*(int)slot/4; i++)
    {
        float v;
        memcpy(&v, (const unsigned char *)b->vertices + 4u*(unsigned int)i, sizeof(v));
        if (!a->records && !rtFinite(v)) { *at = i; return "a NaN/Inf in the vertices"; }
    }
    return NULL;
}

// RblBatchAddMany leaves a batch as the same billboards through RblBatchAdd one at a time do, bit
// for bit: slots (records in the mapped buffer, on the CPU, or vertices), runs, counts, the
// back-facing flag, the return (billboards not skipped) and one log line a batch; chunks of every
// size from 1 (splitting fours at each lane) to the whole set, a batch growing during a call, two
// materials; a perspective view (6 culling planes), no culling, an orthographic view (backs seen
// everywhere or per axis), sorted (records kept on the CPU), a shadow pass (4 planes, AXIS
// spheres widened), pivots at the planes' edges, and backs seen only on culled cards (no flag). Bad calls (NULL, negative count) log once and change nothing
static void test_batch_add_many_equals_adding_one_at_a_time_bit_for_bit(void)
{
    enum { MANY = 3000 };
    static RblBillboard set[MANY];
    static const int chunks[] = { 1, 2, 3, 4, 5, 7, 8, 13, 64, 1, 1, 600, 3 }, whole[] = { MANY };
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1;
    Shader lit = RblLoadLitShader(desc);
    Material m[2] = { LoadMaterialDefault(), LoadMaterialDefault() };
    m[0].shader = lit; m[1].shader = lit;
    m[1].params[RBL_PARAM_ALPHA_CUTOFF] = 0.5f;
    Camera3D persp = frontCamera(), ortho = frontCamera();
    persp.position = (Vector3){ 0.5f, 1.0f, 6.0f };
    ortho.projection = CAMERA_ORTHOGRAPHIC; ortho.fovy = 6.0f; ortho.position = (Vector3){ 1.0f, 2.0f, 6.0f };
    RenderTexture2D rt = LoadRenderTexture(64, 64);
    RblLight sun = litDirectional((Vector3){ -0.4f, -1.0f, -0.3f }, 1.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1;
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    const char *names[7] = { "perspective, culled", "no culling", "orthographic", "sorted", "shadow pass", "two materials, whole set", "backs seen only behind the eye" };
    int compared = 0, mapped = 0, culledAll = 0, skippedAll = 0, backs = 0;
    long long foursAll = 0, singlesAll = 0;
    for (int c = 0; c < 7; c++)
    for (int seedIndex = 0; seedIndex < 3; seedIndex++)
    {
        manySet(7u + 13u*(unsigned int)seedIndex + 101u*(unsigned int)c, set, MANY);
        for (int k = 0; (c == 6) && (k < MANY); k++)
        {
            // front-facing cards, every 9th behind the eye (culled): the batch sees no back
            set[k].facing = RBL_FACING_CAMERA_PLANE; set[k].up = (Vector3){ 0.0f, 1.0f, 0.0f }; set[k].axis = (Vector3){ 0.0f, 0.0f, 0.0f };
            if (k % 9 == 0) set[k].position.z = 9.0f;
        }
        const bool grows = (seedIndex == 1);       // a read-back at growth keeps the rest on the CPU
        RblBatch one = RblLoadBatch(grows? 64 : MANY), many = RblLoadBatch(grows? 64 : MANY);
        one.noCull = many.noCull = (c == 1);
        one.sort = many.sort = (c == 3)? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE;
        Camera3D cam = (c == 2)? ortho : persp;
        ManyRun a = { 0 }, b = { 0 };
        const char *why = "batches not loaded";
        int at = -1;
        bool shadow = (c == 4), wasMapped = false, manyBack = false;
        if (shadow && !RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 4.0f)) { RT_CHECK(false, "shadow pass refused"); continue; }
        if (!shadow) { BeginTextureMode(rt); BeginMode3D(cam); }
        rbl__BatchState *sa = rbl__batchState(&one), *sb = rbl__batchState(&many);
        if ((sa != NULL) && (sb != NULL))
        {
            RblBeginBatch(&one, cam);
            manyEdges(sa, 5u + (unsigned int)c, set, MANY);
            RblEndBatch(&one);
            a = manyAdd(&one, cam, m, (c == 5)? 2 : 1, set, MANY, NULL, 0);
            long long fours = rbl__state.stretchFours, singles = rbl__state.stretchSingles;
            b = manyAdd(&many, cam, m, (c == 5)? 2 : 1, set, MANY, (c == 5)? whole : chunks, (c == 5)? 1 : (int)(sizeof(chunks)/sizeof(chunks[0])));
            wasMapped = sb->mapped != NULL;
            foursAll += rbl__state.stretchFours - fours; singlesAll += rbl__state.stretchSingles - singles;
            why = manyDiffer(sa, sb, &at);
            backs += sb->backFacing;
            manyBack = sb->backFacing;
        }
        RblEndBatch(&one); RblEndBatch(&many);
        if (shadow) RblEndShadowMap(&map);
        else { EndMode3D(); EndTextureMode(); }
        RT_CHECK(why == NULL, "%s, seed %d: %s differ (at %d); one at a time %d added %d culled %d skipped, many %d / %d / %d",
                 names[c], seedIndex, why, at, a.added, a.culled, a.skipped, b.added, b.culled, b.skipped);
        RT_CHECK((a.added == b.added) && (a.added == a.count), "%s: returns %d vs %d (count %d, culled included)", names[c], a.added, b.added, a.count);
        RT_CHECK((a.warned == 1) && (b.warned == 1), "%s: %d and %d log lines (one a batch)", names[c], a.warned, b.warned);
        RT_CHECK(wasMapped == (recMaps() && (c != 3) && !grows), "%s, seed %d: mapped %d", names[c], seedIndex, wasMapped);
        RT_CHECK((c != 6) || !manyBack, "%s: a culled card's back turned culling off", names[c]);
        compared += (why == NULL); mapped += wasMapped; culledAll += a.culled; skippedAll += a.skipped;
        RblUnloadBatch(&one); RblUnloadBatch(&many);
    }
    printf("    %d of 21 batches of %d equal bit for bit (%d mapped; %d culled, %d skipped in all; %d seen from behind)\n", compared, MANY, mapped, culledAll, skippedAll, backs);
    RT_CHECK((culledAll > 3000) && (skippedAll > 1000) && (backs >= 6), "the set must cull, skip and show backs: %d / %d / %d", culledAll, skippedAll, backs);
    // The stretches took most of them (else the comparison tested the general steps only): four lanes
    // at a time where the build has SSE2, one at a time otherwise
    printf("    stretches took %lld fours and %lld one at a time of %d\n", foursAll, singlesAll, 21*MANY);
    // (GLSL 1 contexts keep vertices: no records, no stretches)
#if defined(RBL__SSE2)
    RT_CHECK(rtGlsl3()? (4*foursAll > 21*MANY/2) : (foursAll + singlesAll == 0), "four-lane stretches took %lld of %d (%lld one at a time)", 4*foursAll, 21*MANY, singlesAll);
#else
    RT_CHECK((foursAll == 0) && (rtGlsl3()? (singlesAll > 21*MANY/2) : (singlesAll == 0)), "stretches took %lld of %d", singlesAll, 21*MANY);
#endif
    // Bad calls: one line each, nothing added
    RblBatch batch = RblLoadBatch(0);
    BeginTextureMode(rt); BeginMode3D(persp);
    RblBeginBatch(&batch, persp);
    int before = warnings;
    int r0 = RblBatchAddMany(&batch, m[0], NULL, 5), r1 = RblBatchAddMany(&batch, m[0], set, -1), r2 = RblBatchAddMany(&batch, m[0], set, 0);
    RT_CHECK((r0 == 0) && (r1 == 0) && (r2 == 0) && (batch.count == 0) && (batch.skipped == 0) && (warnings - before == 2),
             "bad calls: returns %d %d %d, count %d, skipped %d, %d lines (2 expected)", r0, r1, r2, batch.count, batch.skipped, warnings - before);
    RblEndBatch(&batch);
    before = warnings;
    int r3 = RblBatchAddMany(&batch, m[0], set, 4);
    RT_CHECK((r3 == 0) && (warnings - before == 1), "outside RblBeginBatch: %d added, %d lines", r3, warnings - before);
    EndMode3D(); EndTextureMode();
    RblUnloadBatch(&batch);
    RblUnloadShadowMap(&map);
    UnloadRenderTexture(rt);
    MemFree(m[0].maps); MemFree(m[1].maps);
    RblUnloadLitShader(&lit);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_RECORDS_TESTS \
    RT_TEST(test_batch_records_draw_what_vertices_draw_lit_mirrored_turned_and_rounded), \
    RT_TEST(test_batch_records_cast_fill_the_gbuffer_sort_and_turn_to_vertices_like_vertices), \
    RT_TEST(test_batch_records_turned_to_vertices_carry_their_caster_identities), \
    RT_TEST_GLSL3(test_batch_records_vertex_stage_emits_the_vertex_paths_corners_normals_and_tangents), \
    RT_TEST_GLSL3(test_batch_records_mapped_read_back_bit_for_bit_and_draw_as_kept_ones), \
    RT_TEST(test_batch_add_many_equals_adding_one_at_a_time_bit_for_bit)
