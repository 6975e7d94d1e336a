// Cross-fade between two atlas frames (RblLitShaderDesc.crossFade; RblBatchAddFade, RblDrawBillboardFade,
// RblInstancedDesc.fades): at 1 texel per pixel (orthographic camera), point-sampled sheets.
// Weight 0 and 1 are the single-frame renderings of the program without the option (0/255); weight
// 0.5 the double-precision mean of the two texels in linear light; a second frame stored rotated
// mixes like its upright twin, its normal in its own tangent axes; alpha mixes linearly, colour by
// coverage, the cutoff reads the mixed alpha. Batch, immediate and instanced paths; the G-buffer's
// geometry pass. Included by test_gpu_main.c (normalTexel: gpu_common.h).

#define FADE_RT 64

// Frames a (0,0 16x8), b (16,0 16x8) upright, c = b stored turned clockwise in the 8x16 block at 32,0
static const char fadeAtlasJson[] =
    "{\"frames\": {\"a\": {\"frame\": {\"x\":0,\"y\":0,\"w\":16,\"h\":8}}, \"b\": {\"frame\": {\"x\":16,\"y\":0,\"w\":16,\"h\":8}},"
    " \"c\": {\"frame\": {\"x\":32,\"y\":0,\"w\":16,\"h\":8}, \"rotated\": true}}, \"meta\": {\"size\": {\"w\":48,\"h\":16}}}";

// A 48x16 sheet: frames a and b (the two 16x8 tiles) and c, b's tile turned clockwise; texels
// written as they are (ImageDraw would blend alpha)
static Image fadeSheetExact(Image a, Image b)
{
    Image sheet = GenImageColor(48, 16, BLANK);
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++)
        {
            ImageDrawPixel(&sheet, x, y, GetImageColor(a, x, y));
            ImageDrawPixel(&sheet, 16 + x, y, GetImageColor(b, x, y));
            ImageDrawPixel(&sheet, 32 + (7 - y), x, GetImageColor(b, x, y));     // clockwise: (x, y) -> (h-1-y, x)
        }
    return sheet;
}

static Camera3D fadeCamera(void)
{
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0, 0, 10 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = (float)FADE_RT; cam.projection = CAMERA_ORTHOGRAPHIC;
    return cam;
}

// A 16x8 card centred at (x, y): pixel (32 + x - 8 + i, 32 - y - 4 + j) shows frame texel (i, j)
static RblBillboard fadeCard(const RblAtlas *atlas, int frame, float x, float y)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    RblAtlasBillboard(atlas, frame, 1.0f, &b);
    b.position = (Vector3){ x, y, 0.0f };
    b.origin = (Vector2){ 8.0f, 4.0f };
    return b;
}

static RblFade fadeFrom(const RblAtlas *atlas, int frame, float weight)
{
    RblFade f;
    memset(&f, 0, sizeof(f));
    f.source = atlas->frames[frame].source;
    f.flags = atlas->frames[frame].flags;
    f.weight = weight;
    return f;
}

enum { FADE_BATCH = 0, FADE_IMMEDIATE, FADE_INSTANCED };
static const char *const fadePathName[3] = { "batch", "immediate", "instanced" };

// n cards drawn by one path into a cleared target: with cardFades (NULL = none) through the fade
// entry points (instanced: RblInstancedDesc.fades), else the plain ones
static Image fadeRender(int path, Material m, const RblBillboard *cards, const RblFade *cardFades, int n, int sort)
{
    Camera3D cam = fadeCamera();
    RenderTexture2D rt = LoadRenderTexture(FADE_RT, FADE_RT);
    RblBatch batch = RblLoadBatch(n);
    batch.sort = sort;
    RblInstanceBuffer buf;
    memset(&buf, 0, sizeof(buf));
    RblInstance inst[8];
    RblFade fades[8];
    BeginTextureMode(rt); ClearBackground(BLANK); BeginMode3D(cam);
    if (path == FADE_INSTANCED)
    {
        buf = RblLoadInstanceBuffer(n);
        for (int i = 0; i < n; i++)
        {
            memset(&inst[i], 0, sizeof(inst[i]));
            inst[i].position = cards[i].position; inst[i].size = cards[i].size; inst[i].origin = cards[i].origin;
            inst[i].source = cards[i].source; inst[i].flags = cards[i].flags;
            if (cardFades != NULL) fades[i] = cardFades[i];
        }
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.fades = (cardFades != NULL)? fades : NULL;
        d.sort = sort;
        RT_CHECK(RblDrawInstanced(&buf, cam, m, d, inst, n) == n, "instanced draw");
    }
    else if (path == FADE_IMMEDIATE)
    {
        for (int i = 0; i < n; i++)
        {
            if (cardFades != NULL) RblDrawBillboardFade(cam, m, cards[i], cardFades[i]);
            else RblDrawBillboard(cam, m, cards[i]);
        }
    }
    else
    {
        RblBeginBatch(&batch, cam);
        for (int i = 0; i < n; i++) RT_CHECK((cardFades != NULL)? RblBatchAddFade(&batch, m, &cards[i], &cardFades[i]) : RblBatchAdd(&batch, m, &cards[i]), "card %d refused", i);
        RblEndBatch(&batch);
    }
    EndMode3D(); EndTextureMode();
    Image out = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    if (path == FADE_INSTANCED) RblUnloadInstanceBuffer(&buf);
    return out;
}

// Largest channel difference (rgb) over the whole image (a and b of one size)
static int fadeImageDiff(Image a, Image b)
{
    int worst = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++)
        {
            Color p = rtPixel(a, x, y), q = rtPixel(b, x, y);
            int d = abs(p.r - q.r);
            if (abs(p.g - q.g) > d) d = abs(p.g - q.g);
            if (abs(p.b - q.b) > d) d = abs(p.b - q.b);
            if (d > worst) worst = d;
        }
    return worst;
}

// Largest difference between the card at (cx, cy) and the double mean of tiles a and b (opaque)
static int fadeMeanDiff(Image out, Image a, Image b, double w, float cx, float cy)
{
    int worst = 0;
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 16; i++)
        {
            Color p = GetImageColor(a, i, j), q = GetImageColor(b, i, j), got = rtPixel(out, (int)(32 + cx - 8) + i, (int)(32 - cy - 4) + j);
            const unsigned char pc[3] = { p.r, p.g, p.b }, qc[3] = { q.r, q.g, q.b }, gc[3] = { got.r, got.g, got.b };
            for (int k = 0; k < 3; k++)
            {
                double want = 255.0*srgbEncode((1.0 - w)*srgbDecode(pc[k]/255.0) + w*srgbDecode(qc[k]/255.0));
                int d = (int)ceil(fabs(want - gc[k]) - 0.5);
                if (d > worst) worst = d;
            }
        }
    return worst;
}

static Image fadeNoiseTile(unsigned int seed)
{
    Image img = GenImageColor(16, 8, BLACK);
    Color *px = (Color *)img.data;
    for (int i = 0; i < 16*8; i++)
    {
        unsigned int r = rtRandom(&seed);
        px[i] = (Color){ (unsigned char)(r & 255), (unsigned char)((r >> 8) & 255), (unsigned char)((r >> 16) & 255), 255 };
    }
    return img;
}

typedef struct { RblAtlas atlas; Image tileA, tileB; Texture2D sheet; Shader plain, fade, plainInst, fadeInst; Material mPlain, mFade, mPlainInst, mFadeInst; } FadeRig;

static FadeRig fadeRigLoad(Image tileA, Image tileB, RblLitShaderDesc desc)
{
    FadeRig r;
    memset(&r, 0, sizeof(r));
    r.atlas = RblLoadAtlasFromMemory(fadeAtlasJson, (int)strlen(fadeAtlasJson), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(r.atlas) && (r.atlas.frameCount == 3) && (r.atlas.frames[2].flags & RBL_FRAME_ROTATED), "fixture atlas");
    r.tileA = tileA; r.tileB = tileB;
    Image sheet = fadeSheetExact(tileA, tileB);
    r.sheet = LoadTextureFromImage(sheet);
    UnloadImage(sheet);
    Shader *sh[4] = { &r.plain, &r.fade, &r.plainInst, &r.fadeInst };
    Material *mt[4] = { &r.mPlain, &r.mFade, &r.mPlainInst, &r.mFadeInst };
    for (int k = 0; k < 4; k++)
    {
        RblLitShaderDesc d = desc;
        d.crossFade = (k & 1) != 0;
        d.instanced = (k >= 2);
        if (d.instanced && !rtGlsl3()) continue;
        *sh[k] = RblLoadLitShader(d);
        RT_CHECK(sh[k]->id != 0, "program %d", k);
        *mt[k] = LoadMaterialDefault();
        mt[k]->shader = *sh[k];
        mt[k]->maps[MATERIAL_MAP_ALBEDO].texture = r.sheet;
    }
    return r;
}

static void fadeRigUnload(FadeRig *r)
{
    Shader *sh[4] = { &r->plain, &r->fade, &r->plainInst, &r->fadeInst };
    Material *mt[4] = { &r->mPlain, &r->mFade, &r->mPlainInst, &r->mFadeInst };
    for (int k = 0; k < 4; k++) { if (sh[k]->id != 0) RblUnloadLitShader(sh[k]); if (mt[k]->maps != NULL) MemFree(mt[k]->maps); }
    UnloadTexture(r->sheet);
    UnloadImage(r->tileA); UnloadImage(r->tileB);
    RblUnloadAtlas(&r->atlas);
}

static void test_fade_weights_0_and_1_are_the_single_frames_and_half_is_the_linear_mean(void)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(fadeNoiseTile(11u), fadeNoiseTile(23u), desc);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");      // white ambient: the albedo comes back
    int checks = 0;
    for (int path = 0; path < 3; path++)
    {
        bool inst = (path == FADE_INSTANCED);
        if (inst && !rtGlsl3()) continue;
        Material plain = inst? r.mPlainInst : r.mPlain, fade = inst? r.mFadeInst : r.mFade;
        RblBillboard a = fadeCard(&r.atlas, 0, 0, 0), b = fadeCard(&r.atlas, 1, 0, 0);
        Image onlyA = fadeRender(path, plain, &a, NULL, 1, 0), onlyB = fadeRender(path, plain, &b, NULL, 1, 0);
        RT_CHECK(fadeMeanDiff(onlyA, r.tileA, r.tileB, 0.0, 0, 0) <= 1, "%s: frame a is not its texels", fadePathName[path]);
        // The option compiled in, no fade given: the first frame exactly (a constant weight 0)
        Image none = fadeRender(path, fade, &a, NULL, 1, 0);
        RT_CHECK(fadeImageDiff(none, onlyA) == 0, "%s: crossFade program without a fade differs from the plain program by %d/255", fadePathName[path], fadeImageDiff(none, onlyA));
        UnloadImage(none);
        for (int second = 1; second <= 2; second++)       // b upright, then c (b stored rotated)
        {
            static const float weights[5] = { 0.0f, 1.0f, 1e-6f, 1.0f - 1e-6f, 0.5f };
            for (int k = 0; k < 5; k++)
            {
                RblBillboard card = a;
                RblFade cardFade = fadeFrom(&r.atlas, second, weights[k]);
                Image out = fadeRender(path, fade, &card, &cardFade, 1, 0);
                int dA = fadeImageDiff(out, onlyA), dB = fadeImageDiff(out, onlyB), dMean = fadeMeanDiff(out, r.tileA, r.tileB, weights[k], 0, 0);
                int got = (k == 0 || k == 2)? dA : ((k == 1 || k == 3)? dB : dMean), limit = (k < 2)? 0 : 1;
                printf("    %-9s second %s  weight %-9.7g  vs a %3d  vs b %3d  vs double mean %3d\n", fadePathName[path], (second == 1)? "upright" : "rotated", weights[k], dA, dB, dMean);
                RT_CHECK(got <= limit, "%s, %s second frame, weight %g: %d/255 off (limit %d)", fadePathName[path], (second == 1)? "upright" : "rotated", weights[k], got, limit);
                if (k == 4) RT_CHECK(dA > 20 && dB > 20, "weight 0.5 should be neither frame");
                if (got > limit) rtSaveImage(out, fadePathName[path]);
                UnloadImage(out);
                checks++;
            }
        }
        UnloadImage(onlyA); UnloadImage(onlyB);
    }
    printf("    %d renderings compared\n", checks);
    fadeRigUnload(&r);
}

// A batch whose fade stream starts at its second card (the first gets weight 0), sorted back to
// front (the stream follows its quads), and the instanced sort: every card keeps its own pair
static void test_fade_stream_follows_its_cards_through_late_starts_and_sorting(void)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(fadeNoiseTile(5u), fadeNoiseTile(77u), desc);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    static const float wts[3] = { 0.0f, 0.5f, 0.25f };
    for (int path = 0; path < 3; path += 2)
    {
        if ((path == FADE_INSTANCED) && !rtGlsl3()) continue;
        for (int sort = 0; sort < 2; sort++)
        {
            RblBillboard cards[3];
            RblFade cardFades[3];
            for (int i = 0; i < 3; i++)
            {
                cards[i] = fadeCard(&r.atlas, 0, 0.0f, 20.0f - 20.0f*i);
                cards[i].position.z = (float)i;       // depths differ: the sort reverses the order
                memset(&cardFades[i], 0, sizeof(cardFades[i]));
                if (wts[i] > 0.0f) cardFades[i] = fadeFrom(&r.atlas, 2, wts[i]);
            }
            // The batch: the first card through the plain entry point (the stream starts at the second)
            Image out;
            if (path == FADE_BATCH)
            {
                Camera3D cam = fadeCamera();
                RenderTexture2D rt = LoadRenderTexture(FADE_RT, FADE_RT);
                RblBatch batch = RblLoadBatch(3);
                batch.sort = sort? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE;
                BeginTextureMode(rt); ClearBackground(BLANK); BeginMode3D(cam);
                RblBeginBatch(&batch, cam);
                RT_CHECK(RblBatchAdd(&batch, r.mFade, &cards[0]) && RblBatchAddFade(&batch, r.mFade, &cards[1], &cardFades[1]) &&
                         RblBatchAddFade(&batch, r.mFade, &cards[2], &cardFades[2]), "cards refused");
                RblEndBatch(&batch);
                EndMode3D(); EndTextureMode();
                out = rtReadTarget(rt);
                UnloadRenderTexture(rt);
                RblUnloadBatch(&batch);
            }
            else out = fadeRender(path, r.mFadeInst, cards, cardFades, 3, sort? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE);
            for (int i = 0; i < 3; i++)
            {
                int d = fadeMeanDiff(out, r.tileA, r.tileB, wts[i], 0.0f, 20.0f - 20.0f*i);
                RT_CHECK(d <= 1, "%s %s: card %d (weight %g) %d/255 off its mean", fadePathName[path], sort? "sorted" : "unsorted", i, wts[i], d);
            }
            UnloadImage(out);
        }
    }
    fadeRigUnload(&r);
}

// Lambert, one directional light, black ambient, white albedo: the pixel is encode(max(0, N.L)).
// Frame a's normal leans toward the sprite's right, b's toward its up, stored upright and, in c,
// turned clockwise (its texels then hold the vector a holds: read in a's axes it would light as a)
static double fadeLambert(Color na, Color nb, double w, D3 l)
{
    D3 a = dNorm(d3(na.r/255.0*2.0 - 1.0, na.g/255.0*2.0 - 1.0, na.b/255.0*2.0 - 1.0));
    D3 b = dNorm(d3(nb.r/255.0*2.0 - 1.0, nb.g/255.0*2.0 - 1.0, nb.b/255.0*2.0 - 1.0));
    D3 n = dNorm(dAdd(dScale(a, 1.0 - w), dScale(b, w)));     // sprite axes = world axes here (right +X, up +Y, out +Z)
    return 255.0*srgbEncode(fmax(0.0, dDot(n, l)));
}

static void test_fade_normal_mapped_pair_mixes_each_frame_in_its_own_tangent_axes(void)
{
    Color na = normalTexel(0.6f, 0.0f, 0.8f), nb = normalTexel(0.0f, 0.6f, 0.8f);
    Image tileA = GenImageColor(16, 8, na), tileB = GenImageColor(16, 8, nb);
    Image normalSheet = fadeSheetExact(tileA, tileB);
    // c holds b turned clockwise: the texel values are the tile's, the vector turns with the image
    for (int y = 0; y < 16; y++) for (int x = 32; x < 40; x++) ImageDrawPixel(&normalSheet, x, y, normalTexel(0.6f, 0.0f, 0.8f));
    Texture2D normalTex = LoadTextureFromImage(normalSheet);
    UnloadImage(normalSheet);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.material.normalEncoding = RBL_NORMAL_RGB;
    FadeRig r = fadeRigLoad(GenImageColor(16, 8, WHITE), GenImageColor(16, 8, WHITE), desc);
    Material *mats[4] = { &r.mPlain, &r.mFade, &r.mPlainInst, &r.mFadeInst };
    for (int k = 0; k < 4; k++) if (mats[k]->maps != NULL) mats[k]->maps[MATERIAL_MAP_NORMAL].texture = normalTex;
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.color = WHITE; sun.intensity = 1.0f;
    sun.direction = (Vector3){ -1.0f, -2.0f, -2.0f };            // toward the light: (1, 2, 2)/3
    RT_CHECK(renderSetLights(&sun, 1, BLACK), "scene");
    D3 l = d3(1.0/3.0, 2.0/3.0, 2.0/3.0);
    static const float weights[4] = { 0.0f, 0.25f, 0.5f, 1.0f };
    for (int path = 0; path < 3; path++)
    {
        bool inst = (path == FADE_INSTANCED);
        if (inst && !rtGlsl3()) continue;
        for (int second = 1; second <= 2; second++)
            for (int k = 0; k < 4; k++)
            {
                RblBillboard card = fadeCard(&r.atlas, 0, 0, 0);
                RblFade cardFade = fadeFrom(&r.atlas, second, weights[k]);
                Image out = fadeRender(path, inst? r.mFadeInst : r.mFade, &card, &cardFade, 1, 0);
                Color got = rtPixel(out, 32, 32);
                double want = fadeLambert(na, nb, weights[k], l), asIfA = fadeLambert(na, na, weights[k], l);
                printf("    %-9s second %s  weight %.2f  got %3d  want %6.2f  (b read in a's axes: %6.2f)\n", fadePathName[path], (second == 1)? "upright" : "rotated", weights[k], got.r, want, asIfA);
                RT_CHECK(fabs(got.r - want) <= 1.0 && got.r == got.g && got.g == got.b, "%s, %s second frame, weight %g: %d, want %.2f", fadePathName[path], (second == 1)? "upright" : "rotated", weights[k], got.r, want);
                UnloadImage(out);
            }
    }
    fadeRigUnload(&r);
    UnloadTexture(normalTex);
}

// Alpha: a fully transparent green first frame, an opaque blue second. The mixed alpha is linear
// (w), the colour the covered frame's alone (blue, not a green-blue mean), and the cutoff (0.5)
// reads the mixed alpha: drawn over black with alpha blending, blue = 255 w above the cutoff, nothing below
static void test_fade_alpha_mixes_linearly_colour_by_coverage_and_the_cutoff_reads_the_mix(void)
{
    FadeRig r;
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    r = fadeRigLoad(GenImageColor(16, 8, (Color){ 0, 255, 0, 0 }), GenImageColor(16, 8, (Color){ 0, 0, 255, 255 }), desc);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    static const float weights[4] = { 0.3f, 0.49f, 0.51f, 0.8f };
    for (int path = 0; path < 3; path++)
    {
        bool inst = (path == FADE_INSTANCED);
        if (inst && !rtGlsl3()) continue;
        for (int k = 0; k < 4; k++)
        {
            RblBillboard card = fadeCard(&r.atlas, 0, 0, 0);
            RblFade cardFade = fadeFrom(&r.atlas, 2, weights[k]);
            Image out = fadeRender(path, inst? r.mFadeInst : r.mFade, &card, &cardFade, 1, 0);
            Color got = rtPixel(out, 32, 32);
            double blue = (weights[k] >= 0.5f)? 255.0*weights[k] : 0.0;
            RT_CHECK(got.r == 0 && got.g == 0 && fabs(got.b - blue) <= 1.0, "%s weight %g: got (%d, %d, %d), want (0, 0, %.1f)", fadePathName[path], weights[k], got.r, got.g, got.b, blue);
            UnloadImage(out);
        }
    }
    fadeRigUnload(&r);
}

// The G-buffer's geometry pass shares the material code: a deferred crossFade variant stores the
// mixed albedo, lit by a white ambient back to the double mean (within the G-buffer's 8-bit albedo)
static void test_fade_deferred_geometry_pass_stores_the_mixed_frame(void)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(fadeNoiseTile(31u), fadeNoiseTile(47u), desc);
    desc.deferred = true;
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = FADE_RT; gd.height = FADE_RT;
    RblGBuffer g = RblLoadGBuffer(gd);
    RT_CHECK(RblIsGBufferValid(g), "G-buffer");
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    for (int instanced = 0; instanced < 2; instanced++)
    {
        desc.crossFade = true;
        desc.instanced = (instanced == 1);
        Shader geo = RblLoadLitShader(desc);
        Material m = LoadMaterialDefault();
        m.shader = geo;
        m.maps[MATERIAL_MAP_ALBEDO].texture = r.sheet;
        RblBillboard card = fadeCard(&r.atlas, 0, 0, 0);
        RblFade cardFade = fadeFrom(&r.atlas, 2, 0.5f);
        Camera3D cam = fadeCamera();
        RT_CHECK(RblBeginGBuffer(&g, cam), "geometry pass");
        RblInstanceBuffer buf = RblLoadInstanceBuffer(1);
        if (instanced)
        {
            RblInstance in;
            memset(&in, 0, sizeof(in));
            in.position = card.position; in.size = card.size; in.origin = card.origin; in.source = card.source; in.flags = card.flags;
            RblInstancedDesc d;
            memset(&d, 0, sizeof(d));
            d.fades = &cardFade;
            RT_CHECK(RblDrawInstanced(&buf, cam, m, d, &in, 1) == 1, "instanced geometry draw");
        }
        else RblDrawBillboardFade(cam, m, card, cardFade);
        RblEndGBuffer(&g);
        RT_CHECK(RblDrawDeferredLights(&g), "lights");
        RenderTexture2D rt = LoadRenderTexture(FADE_RT, FADE_RT);
        BeginTextureMode(rt); ClearBackground(BLANK); RblResolveGBuffer(&g); EndTextureMode();
        Image out = rtReadTarget(rt);
        int d = fadeMeanDiff(out, r.tileA, r.tileB, 0.5, 0, 0);
        printf("    %s geometry pass, weight 0.5: %d/255 from the double mean\n", instanced? "instanced" : "immediate", d);
        RT_CHECK(d <= 1, "%s: %d/255 from the double mean", instanced? "instanced" : "immediate", d);
        UnloadImage(out);
        UnloadRenderTexture(rt);
        RblUnloadInstanceBuffer(&buf);
        RblUnloadLitShader(&geo);
        MemFree(m.maps);
    }
    RblUnloadGBuffer(&g);
    fadeRigUnload(&r);
}

// Bad fades: one RBL line each, nothing drawn (immediate), the instance skipped (instanced)
static void test_fade_bad_weights_and_sources_are_refused_with_one_line(void)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(fadeNoiseTile(3u), fadeNoiseTile(4u), desc);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    const float inf = INFINITY, nan = NAN;
    const float bad[5] = { nan, inf, -inf, -0.25f, 1.5f };
    for (int k = 0; k < 6; k++)
    {
        RblBillboard card = fadeCard(&r.atlas, 0, 0, 0);
        RblFade cardFade = fadeFrom(&r.atlas, 1, 0.5f);
        if (k < 5) cardFade.weight = bad[k];
        else cardFade.source.width = nan;
        int before = warnings;
        Image out = fadeRender(FADE_IMMEDIATE, r.mFade, &card, &cardFade, 1, 0);
        Color c = rtPixel(out, 32, 32);
        RT_CHECK(warnings == before + 1 && c.r == 0 && c.g == 0 && c.b == 0 && c.a == 0, "bad fade %d: %d lines, pixel (%d, %d, %d, %d)", k, warnings - before, c.r, c.g, c.b, c.a);
        UnloadImage(out);
    }
    if (rtGlsl3())
    {
        RblInstanceBuffer buf = RblLoadInstanceBuffer(3);
        RblInstance in[3];
        RblFade fades[3];
        memset(in, 0, sizeof(in)); memset(fades, 0, sizeof(fades));
        for (int i = 0; i < 3; i++) { in[i].position = (Vector3){ 20.0f*(i - 1), 0, 0 }; in[i].size = (Vector2){ 16, 8 }; in[i].origin = (Vector2){ 8, 4 }; in[i].source = r.atlas.frames[0].source; fades[i].weight = 0.5f; fades[i].source = r.atlas.frames[1].source; }
        fades[1].weight = nan;
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.fades = fades;
        Camera3D cam = fadeCamera();
        RenderTexture2D rt = LoadRenderTexture(FADE_RT, FADE_RT);
        int before = warnings;
        BeginTextureMode(rt); ClearBackground(BLANK); BeginMode3D(cam);
        int drawn = RblDrawInstanced(&buf, cam, r.mFadeInst, d, in, 3);
        EndMode3D(); EndTextureMode();
        Image out = rtReadTarget(rt);
        RT_CHECK(drawn == 2 && buf.skipped == 1 && warnings == before + 1, "NaN fade weight: drawn %d, skipped %d, %d lines", drawn, buf.skipped, warnings - before);
        RT_CHECK(rtPixel(out, 32, 32).a == 0 && fadeMeanDiff(out, r.tileA, r.tileB, 0.5, -20, 0) <= 1 && fadeMeanDiff(out, r.tileA, r.tileB, 0.5, 20, 0) <= 1,
                 "the bad instance was drawn or its neighbours lost their fades");
        UnloadImage(out);
        UnloadRenderTexture(rt);
        RblUnloadInstanceBuffer(&buf);
    }
    fadeRigUnload(&r);
}

// One FIXED faded card drawn by the given path (a shadow pass's caster callback)
static void fadeDrawCaster(int path, Camera3D viewer, Material m, RblBillboard b, RblFade f)
{
    if (path == FADE_IMMEDIATE) RblDrawBillboardFade(viewer, m, b, f);
    else if (path == FADE_BATCH)
    {
        RblBatch batch = RblLoadBatch(4);
        RblBeginBatch(&batch, viewer);
        RblBatchAddFade(&batch, m, &b, &f);
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
    }
    else
    {
        RblInstanceBuffer buf = RblLoadInstanceBuffer(4);
        RblInstance in;
        memset(&in, 0, sizeof(in));
        in.position = b.position; in.size = b.size; in.origin = b.origin; in.source = b.source; in.flags = b.flags;
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = RBL_FACING_FIXED; d.axis = b.axis; d.up = b.up; d.fades = &f;
        RT_CHECK(RblDrawInstanced(&buf, viewer, m, d, &in, 1) == 1, "instanced caster not drawn");
        RblUnloadInstanceBuffer(&buf);
    }
}

// Shadows: a faded card casts its mixed cut-out. Frame a opaque, frame b transparent: the mixed
// alpha is 1 - w, against the cutoff 0.5 a card at w 0.3 casts and one at w 0.7 does not (a caster
// reading frame a alone would cast both); on every billboard path (test_shadows.c's floor and light)
typedef struct FadeShadowCard { int path; float weight; } FadeShadowCard;
static void fadeShadowCaster(Material m, Camera3D viewer, void *ctx)
{
    const FadeShadowCard *c = (const FadeShadowCard *)ctx;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ 0.0f, 0.0f, 1.0f }; b.size = (Vector2){ 2.0f, 2.0f }; b.origin = (Vector2){ 1.0f, 1.0f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    b.source = (Rectangle){ 0, 0, 32, 32 };
    RblFade f;
    memset(&f, 0, sizeof(f));
    f.source = (Rectangle){ 32, 0, 32, 32 }; f.weight = c->weight;
    fadeDrawCaster(c->path, viewer, m, b, f);
}

static void test_fade_shadow_casters_cut_out_the_mixed_alpha_on_every_path(void)
{
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    s.lights[0].direction = (Vector3){ 0.4f, 0.0f, -1.0f };
    Image img = GenImageColor(64, 32, WHITE);
    ImageDrawRectangle(&img, 32, 0, 32, 32, BLANK);
    Texture2D sheet = LoadTextureFromImage(img);
    UnloadImage(img);
    int cx = (int)((0.4f + SH_VIEW*0.5f)/SH_VIEW*SH_TARGET), cy = SH_TARGET/2;
    for (int path = 0; path < (rtGlsl3()? 3 : 2); path++)
        for (int k = 0; k < 2; k++)
        {
            FadeShadowCard card = { path, k? 0.7f : 0.3f };
            Image out = shRender(&s, fadeShadowCaster, &card, sheet, false);
            int centre = rtPixel(out, cx, cy).r, outside = rtPixel(out, cx + 40, cy).r;
            printf("    %-9s weight %.1f: footprint centre %3d, unshadowed floor %3d\n", fadePathName[path], card.weight, centre, outside);
            RT_CHECK(k? (centre > outside - 3) : (centre < outside - 40), "%s weight %.1f: centre %d, unshadowed %d", fadePathName[path], card.weight, centre, outside);
            UnloadImage(out);
        }
    UnloadTexture(sheet);
}

// The option compiles in only when asked: a plain program declares no fade input; a crossFade
// program reads raylib's texcoord2 location 5, hidden from raylib's DrawMesh (locs -1), so a Model
// drawn with it renders exactly as with the plain program (the constant weight 0)
static void test_fade_stream_is_declared_only_with_the_option_and_models_draw_unchanged(void)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(fadeNoiseTile(8u), fadeNoiseTile(9u), desc);
    RT_CHECK(rlGetLocationAttrib(r.plain.id, "vertexTexCoord2") == -1, "plain program declares the fade stream");
    RT_CHECK(rlGetLocationAttrib(r.fade.id, "vertexTexCoord2") == 5, "crossFade program: fade stream at %d, not 5", rlGetLocationAttrib(r.fade.id, "vertexTexCoord2"));
    RT_CHECK(r.fade.locs[SHADER_LOC_VERTEX_TEXCOORD02] == -1, "raylib's DrawMesh would bind texcoord2 to the fade stream");
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    Mesh plane = GenMeshPlane(2.0f, 2.0f, 1, 1);
    Model model = LoadModelFromMesh(plane);
    Camera3D top;
    memset(&top, 0, sizeof(top));
    top.position = (Vector3){ 0, 10, 0 }; top.up = (Vector3){ 0, 0, -1 }; top.fovy = 2.5f; top.projection = CAMERA_ORTHOGRAPHIC;
    Image img[2];
    for (int k = 0; k < 2; k++)
    {
        model.materials[0].shader = k? r.fade : r.plain;
        model.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = r.sheet;
        RenderTexture2D rt = LoadRenderTexture(FADE_RT, FADE_RT);
        BeginTextureMode(rt); ClearBackground(BLANK); BeginMode3D(top);
        RblDrawModel(model, (Vector3){ 0, 0, 0 }, 1.0f, WHITE);
        EndMode3D(); EndTextureMode();
        img[k] = rtReadTarget(rt);
        UnloadRenderTexture(rt);
    }
    int drawn = 0;
    for (int y = 0; y < FADE_RT; y++) for (int x = 0; x < FADE_RT; x++) drawn += (rtPixel(img[0], x, y).a == 255);
    RT_CHECK(drawn > 500, "the plane was not drawn (%d pixels)", drawn);      // the sheet's opaque part
    RT_CHECK(fadeImageDiff(img[0], img[1]) == 0, "a Model drawn with the crossFade program differs by %d/255", fadeImageDiff(img[0], img[1]));
    UnloadImage(img[0]); UnloadImage(img[1]);
    model.materials[0].shader = r.plain;        // the rig unloads its programs; the Model keeps none of its own
    model.materials[0].maps[MATERIAL_MAP_ALBEDO].texture.id = 0;
    model.materials[0].shader.id = 0; model.materials[0].shader.locs = NULL;
    UnloadModel(model);
    fadeRigUnload(&r);
}


// Frames of different trims (issue #16): p upright, q stored turned clockwise, r = q upright, on
// 16x12 canvases (no pivot stated: the bottom centre): p's trim (1,2 10x6), q's and r's (5,1 8x9). The fade quad
// covers the union (1,1 12x9); each frame is fetched only inside its own trim
static const char fadeTrimJson[] =
    "{\"frames\": {"
    "\"p\": {\"frame\": {\"x\":0,\"y\":0,\"w\":10,\"h\":6}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":1,\"y\":2,\"w\":10,\"h\":6}, \"sourceSize\": {\"w\":16,\"h\":12}},"
    "\"q\": {\"frame\": {\"x\":16,\"y\":0,\"w\":8,\"h\":9}, \"rotated\": true, \"trimmed\": true, \"spriteSourceSize\": {\"x\":5,\"y\":1,\"w\":8,\"h\":9}, \"sourceSize\": {\"w\":16,\"h\":12}},"
    "\"r\": {\"frame\": {\"x\":32,\"y\":0,\"w\":8,\"h\":9}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":5,\"y\":1,\"w\":8,\"h\":9}, \"sourceSize\": {\"w\":16,\"h\":12}}},"
    " \"meta\": {\"size\": {\"w\":48,\"h\":16}}}";
// The same frames from libGDX (old form): q turned counter-clockwise (both extents negated), offsets
// counted from the canvas bottom (12 - 2 - 6 = 4 for p, 12 - 1 - 9 = 2 for q and r)
static const char fadeTrimGdx[] =
    "s.png\nsize: 48, 16\n"
    "p\n  rotate: false\n  xy: 0, 0\n  size: 10, 6\n  orig: 16, 12\n  offset: 1, 4\n  index: -1\n"
    "q\n  rotate: true\n  xy: 16, 0\n  size: 8, 9\n  orig: 16, 12\n  offset: 5, 2\n  index: -1\n"
    "r\n  rotate: false\n  xy: 32, 0\n  size: 8, 9\n  orig: 16, 12\n  offset: 5, 2\n  index: -1\n";

// The untrimmed 16x12 canvas of a frame: its picture at its trim, transparent elsewhere (the
// reference rebuilds it from the fixture's numbers, not from the atlas)
static Color fadeTrimCanvas(Image pic, int tx, int ty, int i, int j)
{
    if ((i < tx) || (j < ty) || (i >= tx + pic.width) || (j >= ty + pic.height)) return BLANK;
    return GetImageColor(pic, i - tx, j - ty);
}

// Largest rgb difference between the target and the double reference of canvases a (weight 1 - w)
// and b (w) drawn with alpha blending over a cleared target, no cutoff: mixed alpha A = linear, the
// colour mixed in linear light by coverage (w a_b / A), stored as encode(colour) x A; nothing where
// neither frame lies. Canvas pixel (i, j) is target pixel (24 + i, top + j): the card's pivot at the
// target's centre, FADE_TOP_CENTRED for pivots at the canvas centre (8, 6), FADE_TOP_FEET for the
// bottom centre (8, 12) frames without a stated pivot stand on
#define FADE_TOP_CENTRED 26
#define FADE_TOP_FEET 20
static int fadeTrimDiff(Image out, Image picA, int ax, int ay, Image picB, int bx, int by, double w, int top)
{
    int worst = 0;
    for (int y = 0; y < FADE_RT; y++)
        for (int x = 0; x < FADE_RT; x++)
        {
            int i = x - 24, j = y - top;
            Color ca = fadeTrimCanvas(picA, ax, ay, i, j), cb = fadeTrimCanvas(picB, bx, by, i, j), got = rtPixel(out, x, y);
            double aa = ca.a/255.0, ab = cb.a/255.0, A = (1.0 - w)*aa + w*ab;
            double cover = (A > 0.0)? w*ab/A : 0.0;
            const unsigned char pc[3] = { ca.r, ca.g, ca.b }, qc[3] = { cb.r, cb.g, cb.b }, gc[3] = { got.r, got.g, got.b };
            for (int k = 0; k < 3; k++)
            {
                double want = (A > 0.0)? 255.0*srgbEncode((1.0 - cover)*srgbDecode(pc[k]/255.0) + cover*srgbDecode(qc[k]/255.0))*A : 0.0;
                int d = (int)ceil(fabs(want - gc[k]) - 0.5);
                if (d > worst) worst = d;
            }
            if ((A == 0.0) && (got.a != 0) && (worst < 255)) worst = 255;      // drawn where neither frame lies
        }
    return worst;
}

// Largest rgba difference over the whole target
static int fadeImageDiffRgba(Image a, Image b)
{
    int worst = fadeImageDiff(a, b);
    for (int y = 0; y < FADE_RT; y++) for (int x = 0; x < FADE_RT; x++) if (abs(rtPixel(a, x, y).a - rtPixel(b, x, y).a) > worst) worst = abs(rtPixel(a, x, y).a - rtPixel(b, x, y).a);
    return worst;
}

// The trimmed fixture's 48x16 sheet for pictures p (10x6) and q (8x9): q turned clockwise
// (TexturePacker) or counter-clockwise (libGDX), and upright as r. Opaque texels around every frame
// (a packer without padding puts neighbours there): a fetch not clipped to its frame's trim shows them
static Image fadeTrimSheet(Image picP, Image picQ, bool gdx)
{
    Image sheet = GenImageColor(48, 16, (Color){ 255, 0, 255, 255 });
    for (int y = 0; y < 6; y++) for (int x = 0; x < 10; x++) ImageDrawPixel(&sheet, x, y, GetImageColor(picP, x, y));
    for (int y = 0; y < 9; y++)
        for (int x = 0; x < 8; x++)
        {
            if (gdx) ImageDrawPixel(&sheet, 16 + y, 7 - x, GetImageColor(picQ, x, y));      // counter-clockwise in a 9x8 block
            else ImageDrawPixel(&sheet, 16 + (8 - y), x, GetImageColor(picQ, x, y));   // clockwise
            ImageDrawPixel(&sheet, 32 + x, y, GetImageColor(picQ, x, y));
        }
    return sheet;
}

// The trimmed fixture's pictures p (10x6) and q (8x9): random opaque texels from seed
static void fadeTrimPictures(unsigned int seed, Image *picP, Image *picQ)
{
    *picP = GenImageColor(10, 6, BLACK); *picQ = GenImageColor(8, 9, BLACK);
    Image *pics[2] = { picP, picQ };
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < pics[k]->width*pics[k]->height; i++)
        {
            unsigned int v = rtRandom(&seed);
            ((Color *)pics[k]->data)[i] = (Color){ (unsigned char)(v & 255), (unsigned char)((v >> 8) & 255), (unsigned char)((v >> 16) & 255), 255 };
        }
}

// The rig on a trimmed fixture: its sheet (fadeTrimSheet), the atlas read from text, every material
// on the sheet without a cutoff (every partial alpha shows)
static void fadeRigUseTrimSheet(FadeRig *r, Image picP, Image picQ, bool gdx, const char *text)
{
    Image sheet = fadeTrimSheet(picP, picQ, gdx);
    UnloadTexture(r->sheet);
    r->sheet = LoadTextureFromImage(sheet);
    UnloadImage(sheet);
    RblUnloadAtlas(&r->atlas);
    r->atlas = RblLoadAtlasFromMemory(text, (int)strlen(text), RBL_ATLAS_AUTO);
    Material *mats[4] = { &r->mPlain, &r->mFade, &r->mPlainInst, &r->mFadeInst };
    for (int k = 0; k < 4; k++)
        if (mats[k]->maps != NULL)
        {
            mats[k]->maps[MATERIAL_MAP_ALBEDO].texture = r->sheet;
            mats[k]->params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;
        }
}

static void test_fade_frames_of_different_trims_each_stay_on_their_canvas_clipped_to_their_trim(void)
{
    Image picP, picQ;
    fadeTrimPictures(1234u, &picP, &picQ);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(GenImageColor(16, 8, BLANK), GenImageColor(16, 8, BLANK), desc);
    int checks = 0;
    for (int gdx = 0; gdx < 2; gdx++)       // TexturePacker (q turned clockwise), libGDX (counter-clockwise)
    {
        fadeRigUseTrimSheet(&r, picP, picQ, gdx, gdx? fadeTrimGdx : fadeTrimJson);
        RT_CHECK(RblIsAtlasValid(r.atlas) && (r.atlas.frameCount == 3), "trimmed fixture atlas %d", gdx);
        int fp = RblAtlasFindFrame(&r.atlas, "p"), fq = RblAtlasFindFrame(&r.atlas, "q"), fr = RblAtlasFindFrame(&r.atlas, "r");
        RT_CHECK((fp >= 0) && (fq >= 0) && (fr >= 0) && (r.atlas.frames[fq].flags & RBL_FRAME_ROTATED) && !(r.atlas.frames[fr].flags & RBL_FRAME_ROTATED), "fixture frames");
        RT_CHECK(!gdx || ((r.atlas.frames[fq].source.width < 0.0f) && (r.atlas.frames[fq].source.height < 0.0f)), "libGDX's turn: extents not negated");
        RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
        // Pairs: upright to rotated, rotated to upright, upright to upright
        const int pairs[3][2] = { { fp, fq }, { fq, fp }, { fp, fr } };
        static const float weights[6] = { 0.0f, 1.0f, 1e-6f, 1.0f - 1e-6f, 0.5f, 0.25f };
        for (int path = 0; path < 3; path++)
        {
            bool inst = (path == FADE_INSTANCED);
            if (inst && !rtGlsl3()) continue;
            Material plain = inst? r.mPlainInst : r.mPlain, fade = inst? r.mFadeInst : r.mFade;
            for (int pr = 0; pr < 3; pr++)
            {
                int f0 = pairs[pr][0], f1 = pairs[pr][1];
                Image pic0 = (f0 == fp)? picP : picQ, pic1 = (f1 == fp)? picP : picQ;
                int x0 = (f0 == fp)? 1 : 5, y0 = (f0 == fp)? 2 : 1, x1 = (f1 == fp)? 1 : 5, y1 = (f1 == fp)? 2 : 1;
                RblBillboard single[2];
                memset(single, 0, sizeof(single));
                RT_CHECK(RblAtlasBillboard(&r.atlas, f0, 1.0f, &single[0]) && RblAtlasBillboard(&r.atlas, f1, 1.0f, &single[1]), "single frames");
                Image only0 = fadeRender(path, plain, &single[0], NULL, 1, 0), only1 = fadeRender(path, plain, &single[1], NULL, 1, 0);
                // The single frames sit on their canvases (the reference's placement holds)
                RT_CHECK(fadeTrimDiff(only0, pic0, x0, y0, pic1, x1, y1, 0.0, FADE_TOP_FEET) == 0 && fadeTrimDiff(only1, pic0, x0, y0, pic1, x1, y1, 1.0, FADE_TOP_FEET) == 0, "%s pair %d: single frames off their canvases", fadePathName[path], pr);
                for (int k = 0; k < 6; k++)
                {
                    RblBillboard card;
                    RblFade cardFade;
                    memset(&card, 0, sizeof(card));
                    RT_CHECK(RblAtlasBillboardFade(&r.atlas, f0, f1, weights[k], 1.0f, &card, &cardFade), "fade card");
                    Image out = fadeRender(path, fade, &card, &cardFade, 1, 0);
                    int vs0 = fadeImageDiffRgba(out, only0), vs1 = fadeImageDiffRgba(out, only1), ref = fadeTrimDiff(out, pic0, x0, y0, pic1, x1, y1, weights[k], FADE_TOP_FEET);
                    int got = (k == 0)? vs0 : ((k == 1)? vs1 : ref), limit = (k < 2)? 0 : 1;
                    printf("    %-9s %s pair %d (%s -> %s)  weight %-9.7g  vs first %3d  vs second %3d  vs double reference %3d\n", fadePathName[path], gdx? "libGDX" : "TP", pr,
                           (f0 == fq)? "rotated" : "upright", (f1 == fq)? "rotated" : "upright", weights[k], vs0, vs1, ref);
                    RT_CHECK(got <= limit, "%s pair %d weight %g: %d/255 off (limit %d)", fadePathName[path], pr, weights[k], got, limit);
                    if (k >= 4) RT_CHECK(vs0 > 20 && vs1 > 20, "%s pair %d weight %g should be neither frame", fadePathName[path], pr, weights[k]);
                    if (got > limit) rtSaveImage(out, fadePathName[path]);
                    UnloadImage(out);
                    checks++;
                }
                // The instance pair is the billboard's, field for field
                RblInstance in; RblFade f;
                memset(&in, 0, sizeof(in)); memset(&f, 0, sizeof(f));
                RblBillboard card;
                RblFade cardFade;
                memset(&card, 0, sizeof(card));
                RT_CHECK(RblAtlasInstanceFade(&r.atlas, f0, f1, 0.5f, 1.0f, &in, &f) && RblAtlasBillboardFade(&r.atlas, f0, f1, 0.5f, 1.0f, &card, &cardFade), "fade pair");
                RT_CHECK(memcmp(&in.source, &card.source, sizeof(Rectangle)) == 0 && memcmp(&in.size, &card.size, sizeof(Vector2)) == 0 &&
                         memcmp(&in.origin, &card.origin, sizeof(Vector2)) == 0 && in.flags == card.flags && memcmp(&f, &cardFade, sizeof(f)) == 0, "RblAtlasInstanceFade differs from RblAtlasBillboardFade");
                UnloadImage(only0); UnloadImage(only1);
            }
        }
    }
    // Equal trims: RblAtlasBillboardFade is RblAtlasBillboard plus the fade, unclipped (whole quad)
    int fq = RblAtlasFindFrame(&r.atlas, "q"), fr = RblAtlasFindFrame(&r.atlas, "r");
    RblBillboard one, two;
    RblFade twoFade;
    memset(&one, 0, sizeof(one)); memset(&two, 0, sizeof(two));
    RT_CHECK(RblAtlasBillboard(&r.atlas, fq, 2.0f, &one) && RblAtlasBillboardFade(&r.atlas, fq, fr, 0.5f, 2.0f, &two, &twoFade), "equal trims");
    RT_CHECK(memcmp(&one.source, &two.source, sizeof(Rectangle)) == 0 && memcmp(&one.size, &two.size, sizeof(Vector2)) == 0 && memcmp(&one.origin, &two.origin, sizeof(Vector2)) == 0 &&
             memcmp(&twoFade.source, &r.atlas.frames[fr].source, sizeof(Rectangle)) == 0 && twoFade.clip[0].width == 1.0f && twoFade.clip[1].height == 1.0f, "equal trims: not the single frame's quad");
    printf("    %d renderings compared\n", checks);
    UnloadImage(picP); UnloadImage(picQ);
    fadeRigUnload(&r);
}


// The trimmed fixture with pivots that differ: p's at the canvas centre, q's a quarter across
// (4 pixels left of p's), r's a quarter down (3 pixels above p's)
static const char fadePivotJson[] =
    "{\"frames\": {"
    "\"p\": {\"frame\": {\"x\":0,\"y\":0,\"w\":10,\"h\":6}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":1,\"y\":2,\"w\":10,\"h\":6}, \"sourceSize\": {\"w\":16,\"h\":12}, \"pivot\": {\"x\":0.5,\"y\":0.5}},"
    "\"q\": {\"frame\": {\"x\":16,\"y\":0,\"w\":8,\"h\":9}, \"rotated\": true, \"trimmed\": true, \"spriteSourceSize\": {\"x\":5,\"y\":1,\"w\":8,\"h\":9}, \"sourceSize\": {\"w\":16,\"h\":12}, \"pivot\": {\"x\":0.25,\"y\":0.5}},"
    "\"r\": {\"frame\": {\"x\":32,\"y\":0,\"w\":8,\"h\":9}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":5,\"y\":1,\"w\":8,\"h\":9}, \"sourceSize\": {\"w\":16,\"h\":12}, \"pivot\": {\"x\":0.5,\"y\":0.25}}},"
    " \"meta\": {\"size\": {\"w\":48,\"h\":16}}}";

// Largest rgba difference between a mirrored card's frame and the unmirrored frame flipped left to
// right inside the footprint's columns [left, right) (outside them both must match as they are)
static int fadeMirrorDiff(Image mirrored, Image out, int left, int right)
{
    int worst = 0;
    for (int y = 0; y < FADE_RT; y++)
        for (int x = 0; x < FADE_RT; x++)
        {
            int sx = ((x >= left) && (x < right))? left + right - 1 - x : x;
            Color a = rtPixel(mirrored, x, y), b = rtPixel(out, sx, y);
            int d = abs(a.r - b.r);
            if (abs(a.g - b.g) > d) d = abs(a.g - b.g);
            if (abs(a.b - b.b) > d) d = abs(a.b - b.b);
            if (abs(a.a - b.a) > d) d = abs(a.a - b.a);
            if (d > worst) worst = d;
        }
    return worst;
}

// Frames whose pivots differ meet at their pivots (each frame on its own canvas, placed by its own
// pivot, clipped to its trim: the double reference with the canvases shifted by the pivots'
// difference), and a mirrored card (negative width) is the card's mirror image inside the same
// footprint; on every path, upright and rotated frames, weights 0, 1, 0.5 and 0.25
static void test_fade_frames_of_different_pivots_meet_at_their_pivots_and_mirrored_cards_mirror(void)
{
    Image picP, picQ;
    fadeTrimPictures(4321u, &picP, &picQ);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    FadeRig r = fadeRigLoad(GenImageColor(16, 8, BLANK), GenImageColor(16, 8, BLANK), desc);
    fadeRigUseTrimSheet(&r, picP, picQ, false, fadePivotJson);
    int fp = RblAtlasFindFrame(&r.atlas, "p"), fq = RblAtlasFindFrame(&r.atlas, "q"), fr = RblAtlasFindFrame(&r.atlas, "r");
    RT_CHECK(RblIsAtlasValid(r.atlas) && (fp >= 0) && (fq >= 0) && (fr >= 0) && (r.atlas.frames[fq].pivot.x == 0.25f) && (r.atlas.frames[fr].pivot.y == 0.25f), "pivot fixture");
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    // Each frame's trim in the reference's canvas coordinates (the card's pivot at canvas 8, 6, where
    // every frame's pivot lands): p (1, 2); q (5, 1) shifted 4 right (its pivot is 4 pixels into its
    // canvas, not 8); r (5, 1) shifted 3 down (its pivot 3 pixels down, not 6)
    const int pairs[3][2] = { { fp, fq }, { fq, fr }, { fr, fp } };
    static const float weights[4] = { 0.0f, 1.0f, 0.5f, 0.25f };
    int worstRef = 0, worstMirror = 0, renders = 0;
    for (int path = 0; path < 3; path++)
    {
        bool inst = (path == FADE_INSTANCED);
        if (inst && !rtGlsl3()) continue;
        Material fade = inst? r.mFadeInst : r.mFade;
        for (int pr = 0; pr < 3; pr++)
        {
            int f[2] = { pairs[pr][0], pairs[pr][1] }, x[2], y[2];
            Image pic[2];
            for (int k = 0; k < 2; k++)
            {
                pic[k] = (f[k] == fp)? picP : picQ;
                x[k] = (f[k] == fp)? 1 : ((f[k] == fq)? 9 : 5);
                y[k] = (f[k] == fp)? 2 : ((f[k] == fq)? 1 : 4);
            }
            for (int wi = 0; wi < 4; wi++)
            {
                RblBillboard card;
                RblFade cardFade;
                memset(&card, 0, sizeof(card));
                RT_CHECK(RblAtlasBillboardFade(&r.atlas, f[0], f[1], weights[wi], 1.0f, &card, &cardFade), "fade card");
                Image out = fadeRender(path, fade, &card, &cardFade, 1, 0);
                // fadeTrimDiff places canvas pixel (i, j) at target (24 + i, 26 + j): the pivots at the centre
                int ref = fadeTrimDiff(out, pic[0], x[0], y[0], pic[1], x[1], y[1], weights[wi], FADE_TOP_CENTRED);
                int left = (int)lroundf(FADE_RT/2 - card.origin.x), right = left + (int)lroundf(card.size.x);
                card.size.x = -card.size.x;
                Image mirrored = fadeRender(path, fade, &card, &cardFade, 1, 0);
                int mir = fadeMirrorDiff(mirrored, out, left, right);
                int limit = (wi < 2)? 0 : 1;
                printf("    %-9s %s -> %s  weight %-4g  vs double reference %3d  mirrored vs flipped %3d\n", fadePathName[path],
                       (f[0] == fp)? "p" : ((f[0] == fq)? "q (pivot 0.25 across, rotated)" : "r (pivot 0.25 down)"), (f[1] == fp)? "p" : ((f[1] == fq)? "q" : "r"), weights[wi], ref, mir);
                RT_CHECK(ref <= limit && mir <= limit, "%s pair %d weight %g: %d/255 off the reference, mirrored %d/255 off the flipped frame (limit %d)",
                         fadePathName[path], pr, weights[wi], ref, mir, limit);
                if (ref > worstRef) worstRef = ref;
                if (mir > worstMirror) worstMirror = mir;
                if ((ref > limit) || (mir > limit)) { rtSaveImage(out, "pivots"); rtSaveImage(mirrored, "mirrored"); }
                UnloadImage(out); UnloadImage(mirrored);
                renders += 2;
            }
        }
    }
    printf("    %d renderings: worst %d/255 from the reference, %d/255 mirrored vs flipped\n", renders, worstRef, worstMirror);
    UnloadImage(picP); UnloadImage(picQ);
    fadeRigUnload(&r);
}

typedef struct FadeTrimShadowCard { int path; RblBillboard card; RblFade fade; } FadeTrimShadowCard;
static void fadeTrimShadowCaster(Material m, Camera3D viewer, void *ctx)
{
    const FadeTrimShadowCard *c = (const FadeTrimShadowCard *)ctx;
    RblBillboard b = c->card;
    b.position = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    fadeDrawCaster(c->path, viewer, m, b, c->fade);
}

// The G-buffer's geometry pass and the shadow casters share the clip: frames of different trims
// (the fixture above) at weight 0 and 1 store / cast exactly the single frame (0/255; unclipped,
// the opaque neighbours would show), and at 0.5 the G-buffer holds the double mean where both
// frames lie and nothing where neither does
static void test_fade_trimmed_frames_in_the_geometry_pass_and_shadow_casters(void)
{
    Image picP, picQ;
    fadeTrimPictures(99u, &picP, &picQ);
    Image sheetImg = fadeTrimSheet(picP, picQ, false);
    Texture2D sheet = LoadTextureFromImage(sheetImg);
    UnloadImage(sheetImg);
    RblAtlas atlas = RblLoadAtlasFromMemory(fadeTrimJson, (int)strlen(fadeTrimJson), RBL_ATLAS_AUTO);
    int fp = RblAtlasFindFrame(&atlas, "p"), fq = RblAtlasFindFrame(&atlas, "q");
    RT_CHECK(RblIsAtlasValid(atlas) && fp >= 0 && fq >= 0, "fixture");
    if (rtGlsl3())
    {
        RblLitShaderDesc desc;
        memset(&desc, 0, sizeof(desc));
        desc.deferred = true; desc.crossFade = true;
        RblGBufferDesc gd;
        memset(&gd, 0, sizeof(gd));
        gd.width = FADE_RT; gd.height = FADE_RT;
        RblGBuffer g = RblLoadGBuffer(gd);
        RT_CHECK(RblIsGBufferValid(g), "G-buffer");
        RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
        Shader geo = RblLoadLitShader(desc);
        Material m = LoadMaterialDefault();
        m.shader = geo;
        m.maps[MATERIAL_MAP_ALBEDO].texture = sheet;
        Camera3D cam = fadeCamera();
        Image img[5];
        for (int k = 0; k < 5; k++)     // single p, single q, fades at 0, 1, 0.5
        {
            RblBillboard card;
            RblFade cardFade;
            memset(&card, 0, sizeof(card)); memset(&cardFade, 0, sizeof(cardFade));
            if (k < 2) RblAtlasBillboard(&atlas, k? fq : fp, 1.0f, &card);
            else RblAtlasBillboardFade(&atlas, fp, fq, (k == 2)? 0.0f : ((k == 3)? 1.0f : 0.5f), 1.0f, &card, &cardFade);
            RT_CHECK(RblBeginGBuffer(&g, cam), "geometry pass");
            if (k < 2) RblDrawBillboard(cam, m, card);
            else RblDrawBillboardFade(cam, m, card, cardFade);
            RblEndGBuffer(&g);
            RT_CHECK(RblDrawDeferredLights(&g), "lights");
            RenderTexture2D rt = LoadRenderTexture(FADE_RT, FADE_RT);
            BeginTextureMode(rt); ClearBackground(BLANK); RblResolveGBuffer(&g); EndTextureMode();
            img[k] = rtReadTarget(rt);
            UnloadRenderTexture(rt);
        }
        int d0 = fadeImageDiffRgba(img[2], img[0]), d1 = fadeImageDiffRgba(img[3], img[1]), both = 0, none = 0;
        for (int y = 0; y < FADE_RT; y++)
            for (int x = 0; x < FADE_RT; x++)
            {
                Color ca = fadeTrimCanvas(picP, 1, 2, x - 24, y - FADE_TOP_FEET), cb = fadeTrimCanvas(picQ, 5, 1, x - 24, y - FADE_TOP_FEET), got = rtPixel(img[4], x, y);
                if ((ca.a == 0) && (cb.a == 0)) { if (got.a != 0 || got.r != 0 || got.g != 0 || got.b != 0) none++; continue; }
                if ((ca.a == 0) || (cb.a == 0)) continue;
                const unsigned char pc[3] = { ca.r, ca.g, ca.b }, qc[3] = { cb.r, cb.g, cb.b }, gc[3] = { got.r, got.g, got.b };
                for (int c = 0; c < 3; c++)
                {
                    double want = 255.0*srgbEncode(0.5*srgbDecode(pc[c]/255.0) + 0.5*srgbDecode(qc[c]/255.0));
                    int d = (int)ceil(fabs(want - gc[c]) - 0.5);
                    if (d > both) both = d;
                }
            }
        printf("    geometry pass: weight 0 vs p %d, weight 1 vs q %d, weight 0.5 where both lie %d/255 from the double mean, %d pixels drawn where neither lies\n", d0, d1, both, none);
        RT_CHECK(d0 == 0 && d1 == 0 && both <= 1 && none == 0, "deferred trimmed fade: %d %d %d %d", d0, d1, both, none);
        for (int k = 0; k < 5; k++) UnloadImage(img[k]);
        RblUnloadLitShader(&geo);
        MemFree(m.maps);
        RblUnloadGBuffer(&g);
    }
    // Shadows: a card facing the light's floor, canvas 16x12 at 1/8 world unit a pixel
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    for (int path = 0; path < (rtGlsl3()? 3 : 2); path++)
    {
        Image img[4];
        for (int k = 0; k < 4; k++)     // single p, single q, fades at 0 and 1
        {
            FadeTrimShadowCard c;
            memset(&c, 0, sizeof(c));
            c.path = path;
            if (k < 2) RblAtlasBillboard(&atlas, k? fq : fp, 0.125f, &c.card);
            else RblAtlasBillboardFade(&atlas, fp, fq, (k == 2)? 0.0f : 1.0f, 0.125f, &c.card, &c.fade);
            img[k] = shRender(&s, fadeTrimShadowCaster, &c, sheet, false);
        }
        int d0 = fadeImageDiff(img[2], img[0]), d1 = fadeImageDiff(img[3], img[1]), pq = fadeImageDiff(img[0], img[1]);
        printf("    %-9s shadow: weight 0 vs p %d, weight 1 vs q %d (p vs q %d)\n", fadePathName[path], d0, d1, pq);
        RT_CHECK(d0 == 0 && d1 == 0 && pq > 40, "%s trimmed fade casters: %d %d (p vs q %d)", fadePathName[path], d0, d1, pq);
        for (int k = 0; k < 4; k++) UnloadImage(img[k]);
    }
    UnloadTexture(sheet);
    RblUnloadAtlas(&atlas);
    UnloadImage(picP); UnloadImage(picQ);
}

#define RBL_FADE_TESTS \
    RT_TEST(test_fade_weights_0_and_1_are_the_single_frames_and_half_is_the_linear_mean), \
    RT_TEST(test_fade_stream_follows_its_cards_through_late_starts_and_sorting), \
    RT_TEST(test_fade_normal_mapped_pair_mixes_each_frame_in_its_own_tangent_axes), \
    RT_TEST(test_fade_alpha_mixes_linearly_colour_by_coverage_and_the_cutoff_reads_the_mix), \
    RT_TEST_GLSL3(test_fade_deferred_geometry_pass_stores_the_mixed_frame), \
    RT_TEST(test_fade_shadow_casters_cut_out_the_mixed_alpha_on_every_path), \
    RT_TEST(test_fade_stream_is_declared_only_with_the_option_and_models_draw_unchanged), \
    RT_TEST(test_fade_bad_weights_and_sources_are_refused_with_one_line), \
    RT_TEST(test_fade_frames_of_different_trims_each_stay_on_their_canvas_clipped_to_their_trim), \
    RT_TEST(test_fade_trimmed_frames_in_the_geometry_pass_and_shadow_casters), \
    RT_TEST(test_fade_frames_of_different_pivots_meet_at_their_pivots_and_mirrored_cards_mirror)
