// Sprite-sheet atlases (TexturePacker, Aseprite, libGDX), animation playback and N-way sectors.
// Hand-written fixtures (tests/fuzz/corpus/, also the fuzz seeds) with expectations derived by hand
// from each format's documented meaning; the real exporter files of ../shared/atlases when present:
// every file imports and the frames rebuilt from its sheet by raylib's ImageFromImage/ImageRotate*
// (the format's meaning) equal what the frame table puts under a billboard's texture coordinates.

static int atlasWarnings = 0;
static void atlasCountingLog(int level, const char *text, va_list args)
{
    (void)level;
    char line[512];
    vsnprintf(line, sizeof(line), text, args);
    if (strncmp(line, "RBL:", 4) == 0) atlasWarnings++;
}

static bool rectIs(Rectangle r, float x, float y, float w, float h) { return (r.x == x) && (r.y == y) && (r.width == w) && (r.height == h); }
#define CHECK_RECT(r, X, Y, W, H, what) RT_CHECK(rectIs((r), (X), (Y), (W), (H)), "%s: %g %g %g %g, expected %g %g %g %g", (what), (r).x, (r).y, (r).width, (r).height, (double)(X), (double)(Y), (double)(W), (double)(H))

// Texture coordinates of a billboard's corners (BL, BR, TR, TL) for a frame, in texels
static void frameCornerTexels(const RblAtlas *a, int frame, int sheetW, int sheetH, float uv[4][2])
{
    RblCameraFrame view = { { 0, 0, 5 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, false };
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    RT_CHECK(RblAtlasBillboard(a, frame, 1.0f, &b), "frame %d: RblAtlasBillboard refused", frame);
    RblVertex v[4];
    RT_CHECK(RblBillboardVertices(&view, sheetW, sheetH, &b, v), "frame %d: no quad", frame);
    for (int i = 0; i < 4; i++) { uv[i][0] = v[i].texcoord[0]*(float)sheetW; uv[i][1] = v[i].texcoord[1]*(float)sheetH; }
}

static void checkCorners(const RblAtlas *a, int frame, int sheetW, int sheetH, const float want[4][2], const char *what)
{
    float uv[4][2];
    frameCornerTexels(a, frame, sheetW, sheetH, uv);
    static const char *names[4] = { "bottom-left", "bottom-right", "top-right", "top-left" };
    for (int i = 0; i < 4; i++)
        RT_CHECK(fabsf(uv[i][0] - want[i][0]) < 1e-4f && fabsf(uv[i][1] - want[i][1]) < 1e-4f, "%s: %s corner at texel %g %g, expected %g %g", what, names[i], uv[i][0], uv[i][1], want[i][0], want[i][1]);
}

static void checkQuad(const RblAtlas *a, int frame, float scale, float w, float h, float ox, float oy, const char *what)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.flags = RBL_ROUND_CYLINDER;
    RT_CHECK(RblAtlasBillboard(a, frame, scale, &b), "%s: refused", what);
    RT_CHECK(fabsf(b.size.x - w) < 1e-5f && fabsf(b.size.y - h) < 1e-5f, "%s: size %g %g, expected %g %g", what, b.size.x, b.size.y, w, h);
    RT_CHECK(fabsf(b.origin.x - ox) < 1e-5f && fabsf(b.origin.y - oy) < 1e-5f, "%s: origin %g %g, expected %g %g", what, b.origin.x, b.origin.y, ox, oy);
    RT_CHECK((b.flags & RBL_ROUND_CYLINDER) != 0, "%s: other flags lost", what);
    RblInstance in;
    memset(&in, 0, sizeof(in));
    RT_CHECK(RblAtlasInstance(a, frame, scale, &in), "%s: instance refused", what);
    RT_CHECK(memcmp(&in.size, &b.size, sizeof(Vector2)) == 0 && memcmp(&in.origin, &b.origin, sizeof(Vector2)) == 0 && memcmp(&in.source, &b.source, sizeof(Rectangle)) == 0 &&
             ((in.flags & RBL_FRAME_ROTATED) == (b.flags & RBL_FRAME_ROTATED)), "%s: instance fields differ from the billboard's", what);
}

static void test_atlas_texturepacker_hash_and_array_give_the_hand_derived_frames(void)
{
    const char *files[2] = { "tests/fuzz/corpus/texturepacker/hash.json", "tests/fuzz/corpus/texturepacker/array.json" };
    for (int k = 0; k < 2; k++)
    {
        RblAtlas a = RblLoadAtlas(files[k]);
        RT_CHECK(RblIsAtlasValid(&a) && (a.format == RBL_ATLAS_TEXTUREPACKER) && (a.frameCount == 3) && (a.pageCount == 1) && (a.tagCount == 0), "%s: valid %d format %d frames %d", files[k], RblIsAtlasValid(&a), a.format, a.frameCount);
        if (a.frameCount != 3) { RblUnloadAtlas(&a); continue; }
        RT_CHECK(strcmp(a.pages[0].image, "tests/fuzz/corpus/texturepacker/sheet.png") == 0 && a.pages[0].width == 128 && a.pages[0].height == 64, "%s: page %s %dx%d", files[k], a.pages[0].image, a.pages[0].width, a.pages[0].height);
        // "a": trimmed, pivot bottom-centre of the untrimmed 50x60
        const RblAtlasFrame *f = &a.frames[0];
        CHECK_RECT(f->block, 10, 20, 30, 40, "a block"); CHECK_RECT(f->source, 10, 20, 30, 40, "a source"); CHECK_RECT(f->trim, 5, 6, 30, 40, "a trim");
        RT_CHECK(f->flags == 0 && f->size.x == 50 && f->size.y == 60 && f->pivot.x == 0.5f && f->pivot.y == 1.0f, "a: flags/size/pivot");
        // pivot (25, 60) px; quad bottom-left at (5, 46): origin (20, -14) px
        checkQuad(&a, 0, 0.1f, 3.0f, 4.0f, 2.0f, -1.4f, "a at 0.1");
        // "b" + e-acute + U+1F600 (a surrogate pair): rotated, stored 90 degrees clockwise in a 10x20 block
        f = &a.frames[1];
        RT_CHECK(strcmp(f->name, "b\xc3\xa9\xf0\x9f\x98\x80") == 0, "b: name decoded as %s", f->name);
        RT_CHECK(RblAtlasFindFrame(&a, "b\xc3\xa9\xf0\x9f\x98\x80") == 1 && RblAtlasFindFrame(&a, "c") == 2 && RblAtlasFindFrame(&a, "zz") == -1, "find by name");
        CHECK_RECT(f->block, 100, 0, 10, 20, "b block"); CHECK_RECT(f->source, 100, 0, 10, 20, "b source");
        RT_CHECK(f->flags == RBL_FRAME_ROTATED, "b: not rotated");
        // turned clockwise: upright top-left -> block top-right, top-right -> bottom-right,
        // bottom-right -> bottom-left, bottom-left -> top-left
        const float bWant[4][2] = { { 100, 0 }, { 100, 20 }, { 110, 20 }, { 110, 0 } };
        checkCorners(&a, 1, 128, 64, bWant, "b corners");
        checkQuad(&a, 1, 1.0f, 20.0f, 10.0f, 10.0f, 5.0f, "b at 1");
        // "c": rotated and trimmed with a pivot: block 8x12, pivot (4, 12) px, quad bottom-left (3, 10)
        f = &a.frames[2];
        CHECK_RECT(f->block, 64, 32, 8, 12, "c block"); CHECK_RECT(f->trim, 3, 2, 12, 8, "c trim");
        const float cWant[4][2] = { { 64, 32 }, { 64, 44 }, { 72, 44 }, { 72, 32 } };
        checkCorners(&a, 2, 128, 64, cWant, "c corners");
        checkQuad(&a, 2, 0.5f, 6.0f, 4.0f, 0.5f, -1.0f, "c at 0.5");
        RblUnloadAtlas(&a);
        RT_CHECK(a.state == NULL && a.frames == NULL && a.frameCount == 0, "unload zeroes the atlas");
    }
}

static void test_atlas_texturepacker_multipack_follows_related_packs_once(void)
{
    // each pack names the other: both load once, in order, each frame on its own sheet
    RblAtlas a = RblLoadAtlas("tests/fuzz/corpus/texturepacker/multi-0.json");
    RT_CHECK(RblIsAtlasValid(&a) && a.pageCount == 2 && a.frameCount == 2, "pages %d frames %d", a.pageCount, a.frameCount);
    if (a.pageCount == 2 && a.frameCount == 2)
    {
        RT_CHECK(strcmp(a.pages[1].image, "tests/fuzz/corpus/texturepacker/multi-1.png") == 0 && a.frames[0].page == 0 && a.frames[1].page == 1, "page of each frame");
        CHECK_RECT(a.frames[1].block, 4, 0, 12, 4, "two block (rotated 4x12)");
    }
    RblUnloadAtlas(&a);
    // a related pack named outside the atlas's folder is refused (one line), nothing else read
    SaveFileText("build/tests/atlas_related_escape.json", (char *)"{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"related_multi_packs\": [\"../atlas.json\"]}}");
    SetTraceLogCallback(atlasCountingLog);
    atlasWarnings = 0;
    a = RblLoadAtlas("build/tests/atlas_related_escape.json");
    RT_CHECK(!RblIsAtlasValid(&a) && atlasWarnings == 1, "related pack outside the folder: valid %d, %d lines", RblIsAtlasValid(&a), atlasWarnings);
    SetTraceLogCallback(NULL);
    // from memory nothing else is read: one sheet
    int size = 0;
    unsigned char *text = LoadFileData("tests/fuzz/corpus/texturepacker/multi-0.json", &size);
    a = RblLoadAtlasFromMemory((const char *)text, size, RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(&a) && a.pageCount == 1 && a.frameCount == 1, "from memory: pages %d", a.pageCount);
    RblUnloadAtlas(&a);
    UnloadFileData(text);
}

static void test_atlas_aseprite_durations_tags_and_slice_pivots(void)
{
    RblAtlas a = RblLoadAtlas("tests/fuzz/corpus/aseprite/tags.json");
    RT_CHECK(RblIsAtlasValid(&a) && a.format == RBL_ATLAS_ASEPRITE && a.frameCount == 4 && a.tagCount == 4 && a.sliceCount == 3, "format %d frames %d tags %d slices %d", a.format, a.frameCount, a.tagCount, a.sliceCount);
    if (a.frameCount != 4 || a.tagCount != 4 || a.sliceCount != 3) { RblUnloadAtlas(&a); return; }
    const float dur[4] = { 0.125f, 0.25f, 0.5f, 1.0f };
    for (int i = 0; i < 4; i++) RT_CHECK(a.frames[i].duration == dur[i], "frame %d duration %g s", i, a.frames[i].duration);
    const int from[4] = { 0, 1, 0, 1 }, to[4] = { 3, 3, 3, 2 }, dir[4] = { RBL_SPRITE_FORWARD, RBL_SPRITE_REVERSE, RBL_SPRITE_PINGPONG, RBL_SPRITE_PINGPONG_REVERSE }, rep[4] = { 0, 2, 3, 0 };
    for (int t = 0; t < 4; t++)
        RT_CHECK(a.tags[t].from == from[t] && a.tags[t].to == to[t] && a.tags[t].direction == dir[t] && a.tags[t].repeat == rep[t], "tag %s: %d..%d dir %d repeat %d", a.tags[t].name, a.tags[t].from, a.tags[t].to, a.tags[t].direction, a.tags[t].repeat);
    RT_CHECK(RblAtlasFindTag(&a, "ppr") == 3 && RblAtlasFindTag(&a, "none") == -1, "find tag");
    // slice "foot": key 0 bounds (8,20) pivot (8,8) -> canvas (16,28); key 2 (4,16)+(4,8) -> (8,24)
    RT_CHECK(a.slices[1].frame == 0 && a.slices[2].frame == 2 && a.slices[2].hasPivot && !a.slices[0].hasPivot && a.slices[2].pivot.x == 8 && a.slices[2].pivot.y == 24, "slice keys");
    RT_CHECK(a.frames[0].pivot.x == 0.5f && a.frames[0].pivot.y == 0.875f && a.frames[1].pivot.x == 0.5f && a.frames[1].pivot.y == 0.875f, "frames 0-1 pivot %g %g", a.frames[1].pivot.x, a.frames[1].pivot.y);
    RT_CHECK(a.frames[2].pivot.x == 0.25f && a.frames[2].pivot.y == 0.75f && a.frames[3].pivot.x == 0.5f && a.frames[3].pivot.y == 1.5f, "frames 2-3 pivot %g %g / %g %g", a.frames[2].pivot.x, a.frames[2].pivot.y, a.frames[3].pivot.x, a.frames[3].pivot.y);
    // frame 0: trim (2,4) 16x16, pivot (16,28): origin (14, -8); frame 2: trim (8,8), pivot (8,24): origin (0,0)
    checkQuad(&a, 0, 1.0f, 16.0f, 16.0f, 14.0f, -8.0f, "frame 0");
    checkQuad(&a, 2, 0.25f, 4.0f, 4.0f, 0.0f, 0.0f, "frame 2");
    RblUnloadAtlas(&a);
}

static void test_atlas_libgdx_old_and_new_forms_rotate_counter_clockwise_offsets_from_the_bottom(void)
{
    RblAtlas a = RblLoadAtlas("tests/fuzz/corpus/libgdx/old.atlas");
    RT_CHECK(RblIsAtlasValid(&a) && a.format == RBL_ATLAS_LIBGDX && a.frameCount == 3 && a.tagCount == 1 && a.pageCount == 1, "old: frames %d tags %d", a.frameCount, a.tagCount);
    if (a.frameCount == 3 && a.tagCount == 1)
    {
        // index orders the animation: run#0 (file's second region) then run#1
        RT_CHECK(a.frames[0].index == 0 && a.frames[1].index == 1 && strcmp(a.frames[2].name, "icon") == 0, "old: order %d %d %s", a.frames[0].index, a.frames[1].index, a.frames[2].name);
        RT_CHECK(strcmp(a.tags[0].name, "run") == 0 && a.tags[0].from == 0 && a.tags[0].to == 1, "old: tag %s %d..%d", a.tags[0].name, a.tags[0].from, a.tags[0].to);
        CHECK_RECT(a.frames[0].block, 30, 20, 8, 12, "run0 block"); CHECK_RECT(a.frames[0].trim, 4, 2, 8, 12, "run0 trim (16 - 2 - 12 from the top)");
        CHECK_RECT(a.frames[1].block, 10, 20, 12, 8, "run1 block"); CHECK_RECT(a.frames[1].source, 10, 20, -12, -8, "run1 source (counter-clockwise = clockwise + half turn)");
        CHECK_RECT(a.frames[1].trim, 3, 3, 8, 12, "run1 trim");
        RT_CHECK(a.frames[1].flags == RBL_FRAME_ROTATED && a.frames[0].flags == 0, "old: flags");
        // turned counter-clockwise: upright top-left -> block bottom-left, top-right -> top-left,
        // bottom-right -> top-right, bottom-left -> bottom-right
        const float want[4][2] = { { 22, 28 }, { 22, 20 }, { 10, 20 }, { 10, 28 } };
        checkCorners(&a, 1, 64, 64, want, "run1 corners");
        // centre pivot (8, 8) of 16x16; quad bottom-left at (3, 15): origin (5, 7)
        checkQuad(&a, 1, 1.0f, 8.0f, 12.0f, 5.0f, 7.0f, "run1");
    }
    RblUnloadAtlas(&a);
    a = RblLoadAtlas("tests/fuzz/corpus/libgdx/new.atlas");
    RT_CHECK(RblIsAtlasValid(&a) && a.frameCount == 3 && a.pageCount == 2 && a.tagCount == 0, "new: frames %d pages %d", a.frameCount, a.pageCount);
    if (a.frameCount == 3 && a.pageCount == 2)
    {
        RT_CHECK(a.pages[0].width == 64 && a.pages[0].height == 32 && a.pages[1].width == 8 && strcmp(a.pages[1].image, "tests/fuzz/corpus/libgdx/second.png") == 0, "new: pages");
        CHECK_RECT(a.frames[0].block, 1, 2, 6, 10, "a block"); CHECK_RECT(a.frames[0].source, 1, 2, -6, -10, "a source");
        CHECK_RECT(a.frames[0].trim, 2, 3, 10, 6, "a trim (12 - 3 - 6 from the top)");
        RT_CHECK(a.frames[0].size.x == 16 && a.frames[0].size.y == 12 && a.frames[0].flags == RBL_FRAME_ROTATED, "a: size/flags");
        CHECK_RECT(a.frames[1].block, 20, 0, 4, 4, "b block"); CHECK_RECT(a.frames[1].trim, 0, 0, 4, 4, "b trim");
        RT_CHECK(a.frames[2].page == 1 && a.frames[1].page == 0, "pages of frames");
    }
    RblUnloadAtlas(&a);
}

// Same-layout maps (TexturePacker's <sheet>_n.png beside <sheet>.png) use the same frame table:
// packing with the atlas's blocks keeps every frame texel and fills the gutters from frames only
static void test_atlas_blocks_pack_a_same_layout_normal_sheet_per_frame(void)
{
    RblAtlas a = RblLoadAtlas("tests/fuzz/corpus/texturepacker/hash.json");
    if (!RblIsAtlasValid(&a)) { RT_CHECK(false, "fixture"); return; }
    Rectangle blocks[8];
    for (int i = 0; i < a.frameCount; i++) blocks[i] = a.frames[i].block;
    RblMaterialSource src;
    memset(&src, 0, sizeof(src));
    src.albedo = GenImageColor(128, 64, (Color){ 10, 20, 30, 255 });
    src.normal = GenImageColor(128, 64, (Color){ 128, 128, 255, 255 });
    unsigned int seed = 5u;
    for (int i = 0; i < a.frameCount; i++)
    {
        Color c = { (unsigned char)(rtRandom(&seed) | 1), (unsigned char)rtRandom(&seed), (unsigned char)rtRandom(&seed), 255 };
        ImageDrawRectangleRec(&src.albedo, blocks[i], c);
        ImageDrawRectangleRec(&src.normal, blocks[i], (Color){ 200, 128, 200, 255 });
    }
    src.frames = blocks; src.frameCount = a.frameCount;
    RblPackedMaterial packed;
    memset(&packed, 0, sizeof(packed));
    RT_CHECK(RblPackMaterial(&src, &packed), "pack with the atlas blocks refused");
    int inside = 0, gutter = 0;
    for (int y = 0; y < 64 && packed.albedo.data; y++)
        for (int x = 0; x < 128; x++)
        {
            Color got = GetImageColor(packed.albedo, x, y);
            bool in = false;
            for (int i = 0; i < a.frameCount; i++) in = in || CheckCollisionPointRec((Vector2){ x + 0.5f, y + 0.5f }, blocks[i]);
            Color want = GetImageColor(src.albedo, x, y);
            if (in) inside += memcmp(&got, &want, sizeof(Color)) != 0;
            else gutter += (got.r == 10 && got.g == 20 && got.b == 30);     // the sheet's background never leaks in
        }
    RT_CHECK(inside == 0 && gutter == 0, "%d frame texels changed, %d gutter texels kept the background", inside, gutter);
    RblUnloadPackedMaterial(&packed);
    UnloadImage(src.albedo); UnloadImage(src.normal);
    RblUnloadAtlas(&a);
}

// ---- animation: the player against sequences written out by hand ----------------------------
static int seqFrameAt(const int *seq, int n, bool loop, const float *dur, double t, bool *finished)
{
    double total = 0.0;
    for (int i = 0; i < n; i++) total += dur[seq[i]];
    *finished = false;
    if (loop) t = fmod(t, total);
    for (int i = 0; i < n; i++) { if (t < dur[seq[i]]) return seq[i]; t -= dur[seq[i]]; }
    *finished = true;
    return seq[n - 1];
}

static void test_atlas_player_follows_durations_directions_and_repeats(void)
{
    RblAtlas a = RblLoadAtlas("tests/fuzz/corpus/aseprite/tags.json");
    if (!RblIsAtlasValid(&a)) { RT_CHECK(false, "fixture"); return; }
    const float dur[4] = { 0.125f, 0.25f, 0.5f, 1.0f };
    static const int walk[4] = { 0, 1, 2, 3 }, back[6] = { 3, 2, 1, 3, 2, 1 }, pp[10] = { 0, 1, 2, 3, 2, 1, 0, 1, 2, 3 }, ppr[2] = { 2, 1 }, once[4] = { 0, 1, 2, 3 };
    static const int ppr5[6] = { 2, 1, 2, 1, 2, 1 }, pp1[4] = { 0, 1, 2, 3 };     // legs 2 1 | 2 | 1 | 2 | 1; one leg
    struct { const char *tag; int loops; const int *seq; int n; bool loop; } cases[7] = {
        { "walk", 0, walk, 4, true }, { "back", 0, back, 6, false }, { "pp", 0, pp, 10, false }, { "ppr", 0, ppr, 2, true }, { "walk", 1, once, 4, false },
        { "ppr", 5, ppr5, 6, false }, { "pp", 1, pp1, 4, false } };
    for (int c = 0; c < 7; c++)
    {
        RblSpritePlayer p = RblPlaySprite(&a, RblAtlasFindTag(&a, cases[c].tag), cases[c].loops);
        int bad = 0;
        for (int k = 1; k <= 800; k++)     // 1/64 s steps: exact in binary, as every duration here
        {
            RT_CHECK(RblUpdateSprite(&p, &a, 1.0f/64.0f), "update refused");
            bool fin;
            int want = seqFrameAt(cases[c].seq, cases[c].n, cases[c].loop, dur, k/64.0, &fin);
            if ((p.frame != want) || (p.finished != fin)) { if (bad++ < 3) RT_CHECK(false, "%s loops %d at t=%g: frame %d finished %d, expected %d %d", cases[c].tag, cases[c].loops, k/64.0, p.frame, p.finished, want, fin); }
        }
        RT_CHECK(bad == 0, "%s: %d of 800 steps differ", cases[c].tag, bad);
        // one huge step lands where the sequence says (whole periods skipped)
        p = RblPlaySprite(&a, RblAtlasFindTag(&a, cases[c].tag), cases[c].loops);
        RT_CHECK(RblUpdateSprite(&p, &a, 1000.3125f), "huge dt refused");
        bool fin;
        int want = seqFrameAt(cases[c].seq, cases[c].n, cases[c].loop, dur, 1000.3125, &fin);
        RT_CHECK(p.frame == want && p.finished == fin, "%s after 1000.3125 s: frame %d finished %d, expected %d %d", cases[c].tag, p.frame, p.finished, want, fin);
    }
    // cross-fade query: walk at frame 1, half way -> next 2, weight 0.5
    RblSpritePlayer p = RblPlaySprite(&a, 0, 0);
    RblUpdateSprite(&p, &a, 0.25f);
    int next = -1;
    float w = RblSpriteBlend(&p, &a, &next);
    RT_CHECK(p.frame == 1 && next == 2 && w == 0.5f, "blend: frame %d next %d weight %g", p.frame, next, w);
    // RblSpriteFade fills the same pair: the next frame's source and rotation, the weight
    RblFade fade;
    memset(&fade, 0, sizeof(fade));
    RT_CHECK(RblSpriteFade(&p, &a, &fade) && fade.weight == 0.5f && memcmp(&fade.source, &a.frames[2].source, sizeof(Rectangle)) == 0 &&
             fade.flags == (a.frames[2].flags & RBL_FRAME_ROTATED), "fade: weight %g", fade.weight);
    // whole table (tag -1), no durations -> RBL_SPRITE_DEFAULT_FRAME_TIME; bad input refused, untouched
    SetTraceLogCallback(atlasCountingLog);
    atlasWarnings = 0;
    RblSpritePlayer before = p;
    RT_CHECK(!RblUpdateSprite(&p, &a, -1.0f) && !RblUpdateSprite(&p, &a, NAN) && !RblUpdateSprite(NULL, &a, 0.1f) && atlasWarnings == 3 && memcmp(&p, &before, sizeof(p)) == 0, "bad dt: %d lines", atlasWarnings);
    p.frame = 99;
    atlasWarnings = 0;
    RT_CHECK(!RblUpdateSprite(&p, &a, 0.1f) && atlasWarnings == 1 && p.frame == 99, "corrupt player accepted");
    SetTraceLogCallback(NULL);
    RblUnloadAtlas(&a);
}

// The bulk update equals RblUpdateSprite + RblAtlasInstance per instance, bit for bit; a bad player
// is skipped (player and instance untouched) with one line for the call
static void test_atlas_bulk_instance_update_equals_the_per_sprite_calls(void)
{
    RblAtlas a = RblLoadAtlas("tests/fuzz/corpus/aseprite/tags.json");
    if (!RblIsAtlasValid(&a)) { RT_CHECK(false, "fixture"); return; }
    enum { N = 1000 };
    static RblSpritePlayer pa[N], pb[N];
    static RblInstance ia[N], ib[N];
    unsigned int seed = 3u;
    for (int i = 0; i < N; i++)
    {
        pa[i] = RblPlaySprite(&a, (int)(rtRandom(&seed)%5) - 1, (int)(rtRandom(&seed)%3));
        pb[i] = pa[i];
        memset(&ia[i], 0, sizeof(RblInstance));
        ia[i].position = (Vector3){ (float)i, 0, 0 };
        ia[i].flags = (i & 1)? RBL_ROUND_CYLINDER : 0;
        ib[i] = ia[i];
    }
    int diff = 0;
    for (int step = 0; step < 60; step++)
    {
        float dt = (step == 30)? 7.3f : rtRandomRange(&seed, 0.0f, 0.3f);
        RT_CHECK(RblUpdateSpriteInstances(pb, ib, N, &a, dt, 0.05f) == N, "bulk update skipped players");
        for (int i = 0; i < N; i++) { RblUpdateSprite(&pa[i], &a, dt); RblAtlasInstance(&a, pa[i].frame, 0.05f, &ia[i]); }
        diff += memcmp(pa, pb, sizeof(pa)) != 0 || memcmp(ia, ib, sizeof(ia)) != 0;
    }
    RT_CHECK(diff == 0, "%d of 60 steps differ from the per-sprite calls", diff);
    SetTraceLogCallback(atlasCountingLog);
    atlasWarnings = 0;
    pb[5].frame = 99; pb[9].step = 0;
    RblSpritePlayer keep5 = pb[5], keep9 = pb[9];
    RblInstance keepI = ib[5];
    RT_CHECK(RblUpdateSpriteInstances(pb, ib, N, &a, 0.1f, 0.05f) == N - 2 && atlasWarnings == 1, "bad players: %d lines", atlasWarnings);
    RT_CHECK(memcmp(&pb[5], &keep5, sizeof(keep5)) == 0 && memcmp(&pb[9], &keep9, sizeof(keep9)) == 0 && memcmp(&ib[5], &keepI, sizeof(keepI)) == 0, "skipped entries changed");
    atlasWarnings = 0;
    RT_CHECK(RblUpdateSpriteInstances(pb, ib, -1, &a, 0.1f, 0.05f) == 0 && RblUpdateSpriteInstances(NULL, ib, 3, &a, 0.1f, 0.05f) == 0 &&
             RblUpdateSpriteInstances(pb, ib, 3, &a, NAN, 0.05f) == 0 && RblUpdateSpriteInstances(pb, ib, 3, &a, 0.1f, 0.0f) == 0 && atlasWarnings == 4, "refusals: %d lines", atlasWarnings);
    atlasWarnings = 0;
    RT_CHECK(RblUpdateSpriteInstances(NULL, NULL, 0, &a, 0.1f, 0.05f) == 0 && atlasWarnings == 0, "count 0 is a quiet no-op");
    SetTraceLogCallback(NULL);
    RblUnloadAtlas(&a);
}

// ---- N-way sectors at their boundaries -----------------------------------------------------------
static void test_atlas_view_sector_boundaries_for_4_8_16_directions(void)
{
    const int ns[3] = { 4, 8, 16 };
    const float facings[4] = { 0.0f, 90.0f, -37.5f, 720.0f + 22.5f };
    int fails = 0, checks = 0;
    for (int a = 0; a < 3; a++)
        for (int f = 0; f < 4; f++)
            for (int k = 0; k < ns[a]; k++)
            {
                // sector k spans relative angles [k w - w/2, k w + w/2): just inside both ends
                double w = 360.0/ns[a];
                double edges[2] = { k*w - 0.5*w + 0.01, k*w + 0.5*w - 0.01 };
                for (int e = 0; e < 2; e++)
                {
                    double rel = (edges[e] + facings[f])*3.14159265358979323846/180.0;
                    // eye direction from the sprite at that angle about +Y from +Z; the view looks the other way
                    Vector3 view = { (float)-sin(rel)*3.0f, -1.5f, (float)-cos(rel)*3.0f };
                    int s = RblSpriteViewSector(view, facings[f], ns[a]);
                    checks++;
                    if (s != k && fails++ < 5) RT_CHECK(false, "N %d facing %g angle %g: sector %d, expected %d", ns[a], facings[f], edges[e], s, k);
                }
            }
    RT_CHECK(fails == 0 && checks == 2*4*28, "%d of %d boundary checks wrong", fails, checks);
    // a sprite facing +X (90): the eye at +X sees its front (0), at -X its back (N/2); the eye at -Z
    // is a quarter turn counter-clockwise from +X about +Y (+Z -> +X -> -Z): N/4
    RT_CHECK(RblSpriteViewSector((Vector3){ -1, 0, 0 }, 90.0f, 8) == 0 && RblSpriteViewSector((Vector3){ 1, 0, 0 }, 90.0f, 8) == 4, "front/back");
    RT_CHECK(RblSpriteViewSector((Vector3){ 0, 0, 1 }, 90.0f, 8) == 2 && RblSpriteViewSector((Vector3){ 0, 0, -1 }, 90.0f, 8) == 6, "sides");
    RT_CHECK(RblSpriteViewSector((Vector3){ 0, -1, 0 }, 10.0f, 8) == 0, "straight down: front");
    SetTraceLogCallback(atlasCountingLog);
    atlasWarnings = 0;
    RT_CHECK(RblSpriteViewSector((Vector3){ NAN, 0, 1 }, 0, 8) == -1 && RblSpriteViewSector((Vector3){ 0, 0, 1 }, INFINITY, 8) == -1 && RblSpriteViewSector((Vector3){ 0, 0, 1 }, 0, 0) == -1 && atlasWarnings == 3, "bad input: %d lines", atlasWarnings);
    SetTraceLogCallback(NULL);
}

// ---- malformed input: one line, failure, nothing leaked (ASan/LSan in test_cpu_san) ----------------
static void test_atlas_malformed_input_fails_with_one_line(void)
{
    static const char *bad[] = {
        "", " ", "{", "[1]", "{\"frames\": {}}", "{\"frames\": [{\"filename\": \"a\"}]}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":-4,\"h\":4}}]}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":120,\"y\":0,\"w\":16,\"h\":4}}], \"meta\": {\"size\": {\"w\":128,\"h\":128}}}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}, \"rotated\": \"yes\"}]}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}, \"spriteSourceSize\": {\"x\":3,\"y\":0,\"w\":4,\"h\":4}, \"sourceSize\": {\"w\":4,\"h\":4}}]}",
        "{\"frames\": [{\"filename\": \"a\x01\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}]}",
        "{\"frames\": [{\"filename\": \"a\\x\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}]}",
        "{\"frames\": [{\"filename\": \"a\\u12\"}]}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}]} x",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":1e999,\"h\":4}}]}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}, \"duration\": -5}]}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"frameTags\": [{\"name\": \"t\", \"from\": 0, \"to\": 1}]}}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"frameTags\": [{\"name\": \"t\", \"from\": 0, \"to\": 0, \"direction\": \"sideways\"}]}}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"frameTags\": [{\"name\": \"t\", \"from\": 0, \"to\": 0, \"repeat\": \"2x\"}]}}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"slices\": [{\"name\": \"s\", \"keys\": [{\"frame\": 0}]}]}}",
        "{\"frames\": {\"a\": {\"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}, }}",
        "p.png\nr\n  xy: 1\n", "p.png\nr\n  xy: 1, 2\n", "p.png\nsize: 10,10\nr\n  xy: 8,8\n  size: 4,4\n",
        "p.png\nr\n  xy: 0,0\n  size: 4,4\n  orig: 4,4\n  offset: 1,0\n", "p.png\nr\n  rotate: 45\n  xy: 0,0\n  size: 4,4\n",
        "p.png\nsize: 10,10\n", "p.png\nr\n  bounds: 0,0,4,99999999999\n",
    };
    const int n = (int)(sizeof(bad)/sizeof(bad[0]));
    SetTraceLogCallback(atlasCountingLog);
    for (int i = 0; i < n; i++)
    {
        atlasWarnings = 0;
        RblAtlas a = RblLoadAtlasFromMemory(bad[i], (int)strlen(bad[i]), RBL_ATLAS_AUTO);
        RT_CHECK(!RblIsAtlasValid(&a) && a.state == NULL && a.frameCount == 0 && atlasWarnings == 1, "input %d (%.40s): valid %d, %d lines", i, bad[i], RblIsAtlasValid(&a), atlasWarnings);
        RblUnloadAtlas(&a);
    }
    // nesting past the limit
    char deep[300];
    memset(deep, '[', sizeof(deep));
    atlasWarnings = 0;
    RblAtlas a = RblLoadAtlasFromMemory(deep, (int)sizeof(deep), RBL_ATLAS_TEXTUREPACKER);
    RT_CHECK(!RblIsAtlasValid(&a) && atlasWarnings == 1, "deep nesting: %d lines", atlasWarnings);
    // every truncation of the valid fixtures fails cleanly (or parses a shorter valid text)
    const char *files[4] = { "tests/fuzz/corpus/texturepacker/hash.json", "tests/fuzz/corpus/aseprite/tags.json", "tests/fuzz/corpus/libgdx/old.atlas", "tests/fuzz/corpus/libgdx/new.atlas" };
    int wrongLines = 0;
    for (int f = 0; f < 4; f++)
    {
        int size = 0;
        unsigned char *text = LoadFileData(files[f], &size);
        RT_CHECK(text != NULL, "%s missing", files[f]);
        for (int cut = 1; (text != NULL) && (cut < size); cut++)
        {
            char *copy = (char *)malloc((size_t)cut);     // exact size: ASan catches a read past it
            memcpy(copy, text, (size_t)cut);
            atlasWarnings = 0;
            a = RblLoadAtlasFromMemory(copy, cut, RBL_ATLAS_AUTO);
            if (RblIsAtlasValid(&a)) { if (atlasWarnings != 0) wrongLines++; RblUnloadAtlas(&a); }
            else if (atlasWarnings != 1) wrongLines++;
            free(copy);
        }
        UnloadFileData(text);
    }
    RT_CHECK(wrongLines == 0, "%d truncations logged other than one line on failure", wrongLines);
    // refusals of the other functions
    atlasWarnings = 0;
    RblAtlas zero;
    memset(&zero, 0, sizeof(zero));
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    RT_CHECK(RblAtlasFindFrame(&zero, "a") == -1 && !RblAtlasBillboard(&zero, 0, 1.0f, &b) && atlasWarnings == 2, "zero atlas: %d lines", atlasWarnings);
    RblUnloadAtlas(&zero);
    RT_CHECK(atlasWarnings == 3, "unloading a zero atlas: one line");
    SetTraceLogCallback(NULL);
}

// ---- the real exporter files (../shared/atlases) ---------------------------------------------------
#define SHARED_ATLASES "../shared/atlases/"

// Upright image of a frame from its sheet by the format's meaning: ImageFromImage(block), then the
// quarter turn back (TexturePacker stored it clockwise, libGDX counter-clockwise)
static Image uprightFrame(Image sheet, const RblAtlasFrame *f, bool libgdx)
{
    Image img = ImageFromImage(sheet, f->block);
    if (f->flags & RBL_FRAME_ROTATED) { if (libgdx) ImageRotateCW(&img); else ImageRotateCCW(&img); }
    return img;
}

// The frame as a billboard samples it: corner texture coordinates interpolated to each upright
// pixel centre, nearest texel. Returns the number of pixels differing from the upright image.
static int billboardMismatch(const RblAtlas *a, int frame, Image sheet, Image upright)
{
    float uv[4][2];
    frameCornerTexels(a, frame, sheet.width, sheet.height, uv);
    int w = upright.width, h = upright.height, bad = 0;
    Color *sp = LoadImageColors(sheet), *up = LoadImageColors(upright);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
        {
            double s = (x + 0.5)/w, t = (y + 0.5)/h;    // t down: top-left corner is uv[3], bottom-left uv[0]
            double u = uv[3][0]*(1 - s)*(1 - t) + uv[2][0]*s*(1 - t) + uv[0][0]*(1 - s)*t + uv[1][0]*s*t;
            double v = uv[3][1]*(1 - s)*(1 - t) + uv[2][1]*s*(1 - t) + uv[0][1]*(1 - s)*t + uv[1][1]*s*t;
            int tx = (int)floor(u), ty = (int)floor(v);
            if (tx < 0 || ty < 0 || tx >= sheet.width || ty >= sheet.height) { bad++; continue; }
            Color c = sp[ty*sheet.width + tx], d = up[y*w + x];
            if (memcmp(&c, &d, sizeof(Color)) != 0) bad++;
        }
    UnloadImageColors(sp); UnloadImageColors(up);
    return bad;
}

// Untrimmed canvas of a frame (transparent outside its trim)
static Image frameCanvas(Image sheet, const RblAtlasFrame *f, bool libgdx, bool turnedWrong)
{
    Image up = uprightFrame(sheet, f, libgdx);
    if (turnedWrong) { ImageRotateCW(&up); ImageRotateCW(&up); }
    Image canvas = GenImageColor((int)f->size.x, (int)f->size.y, BLANK);
    ImageDraw(&canvas, up, (Rectangle){ 0, 0, (float)up.width, (float)up.height }, f->trim, WHITE);
    UnloadImage(up);
    return canvas;
}

static double meanAbsDiff(Image a, Image b)
{
    if (a.width != b.width || a.height != b.height) return 1e9;
    Color *p = LoadImageColors(a), *q = LoadImageColors(b);
    double sum = 0.0;
    for (int i = 0; i < a.width*a.height; i++) sum += abs(p[i].r - q[i].r) + abs(p[i].g - q[i].g) + abs(p[i].b - q[i].b) + abs(p[i].a - q[i].a);
    UnloadImageColors(p); UnloadImageColors(q);
    return sum/(4.0*a.width*a.height);
}

static void test_atlas_real_exporter_files_import_and_rebuild_from_their_sheets(void)
{
    if (!DirectoryExists(SHARED_ATLASES)) { printf("    (no %s: real-file checks skipped)\n", SHARED_ATLASES); return; }
    static const char *files[] = { "texturepacker/building1.json", "texturepacker/building1-0.json", "texturepacker/test-trim-rotation.json",
        "aseprite/player.json", "aseprite/frames.json", "libgdx/libgdx-packed.atlas", "libgdx/pack.atlas", "libgdx/pack.pack" };
    static const int frames[] = { 5, 5, 4, 24, 25, 5, 71, 71 };
    int checked = 0, rotated = 0;
    for (int i = 0; i < (int)(sizeof(files)/sizeof(files[0])); i++)
    {
        char path[256];
        snprintf(path, sizeof(path), SHARED_ATLASES "%s", files[i]);
        RblAtlas a = RblLoadAtlas(path);
        RT_CHECK(RblIsAtlasValid(&a) && a.frameCount == frames[i], "%s: valid %d, %d frames (expected %d)", files[i], RblIsAtlasValid(&a), a.frameCount, frames[i]);
        if (!RblIsAtlasValid(&a)) continue;
        bool libgdx = (a.format == RBL_ATLAS_LIBGDX);
        for (int p = 0; p < a.pageCount; p++)
        {
            // test-trim-rotation.json names its sheet test.png; the file beside it is the json's name
            Image sheet = LoadImage(a.pages[p].image);
            if (sheet.data == NULL) { char alt[300]; size_t pl = strlen(path); memcpy(alt, path, pl - 5); memcpy(alt + pl - 5, ".png", 5); sheet = LoadImage(alt); }
            RT_CHECK(sheet.data != NULL, "%s: sheet %s not loaded", files[i], a.pages[p].image);
            if (sheet.data == NULL) continue;
            ImageFormat(&sheet, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
            if (a.pages[p].width > 0) RT_CHECK(a.pages[p].width == sheet.width && a.pages[p].height == sheet.height, "%s: stated size %dx%d, sheet %dx%d", files[i], a.pages[p].width, a.pages[p].height, sheet.width, sheet.height);
            for (int f = 0; f < a.frameCount; f++)
            {
                if (a.frames[f].page != p) continue;
                const RblAtlasFrame *fr = &a.frames[f];
                RT_CHECK(fr->block.x + fr->block.width <= sheet.width && fr->block.y + fr->block.height <= sheet.height, "%s %s: block outside the sheet", files[i], fr->name);
                Image up = uprightFrame(sheet, fr, libgdx);
                RT_CHECK(up.width == (int)fr->trim.width && up.height == (int)fr->trim.height, "%s %s: upright %dx%d, trim %gx%g", files[i], fr->name, up.width, up.height, fr->trim.width, fr->trim.height);
                int bad = billboardMismatch(&a, f, sheet, up);
                RT_CHECK(bad == 0, "%s %s: %d pixels differ between the billboard's texture coordinates and the rebuilt frame", files[i], fr->name, bad);
                UnloadImage(up);
                checked++; rotated += (fr->flags & RBL_FRAME_ROTATED) != 0;
            }
            UnloadImage(sheet);
        }
        RblUnloadAtlas(&a);
    }
    RT_CHECK(checked == 210 && rotated == 7, "%d frames checked (%d rotated), expected 210 (7)", checked, rotated);

    // Format meaning, TexturePacker: building1 (scale 0.5, trimmed, 3 stars turned) rebuilt on its
    // 32x32 canvases matches building1-0's untrimmed 64x64 stars halved, closer than the opposite
    // quarter turn would (measured 5.1-5.5/255 against 5.5-5.9: five-pointed stars are nearly
    // symmetric under a half turn, so the margin is small; the billboard check above is exact)
    RblAtlas small = RblLoadAtlas(SHARED_ATLASES "texturepacker/building1.json"), big = RblLoadAtlas(SHARED_ATLASES "texturepacker/building1-0.json");
    Image smallSheet = LoadImage(SHARED_ATLASES "texturepacker/building1.png"), bigSheet = LoadImage(SHARED_ATLASES "texturepacker/building1-0.png");
    if (RblIsAtlasValid(&small) && RblIsAtlasValid(&big) && smallSheet.data && bigSheet.data)
    {
        ImageFormat(&smallSheet, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8); ImageFormat(&bigSheet, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
        for (int s = 1; s <= 4; s++)
        {
            char name[32]; snprintf(name, sizeof(name), "star%d.png", s);
            const RblAtlasFrame *fs = &small.frames[RblAtlasFindFrame(&small, name)], *fb = &big.frames[RblAtlasFindFrame(&big, name)];
            Image cs = frameCanvas(smallSheet, fs, false, false), cw = frameCanvas(smallSheet, fs, false, true), cb = frameCanvas(bigSheet, fb, false, false);
            ImageResize(&cb, 32, 32);
            double right = meanAbsDiff(cs, cb), wrong = meanAbsDiff(cw, cb);
            printf("    %s: mean |diff| %.2f/255 (half-turned: %.2f)\n", name, right, wrong);
            RT_CHECK(right < 6.0 && right < wrong, "%s: rebuilt star differs from the 2x sheet's by %.2f (half-turned %.2f)", name, right, wrong);
            UnloadImage(cs); UnloadImage(cw); UnloadImage(cb);
        }
    }
    else RT_CHECK(false, "building1 sheets");
    UnloadImage(smallSheet); UnloadImage(bigSheet);
    RblUnloadAtlas(&small); RblUnloadAtlas(&big);

    // Format meaning, Aseprite frames.json: tags count each sprite's own frames; the frames they
    // land on are the ones named "<tag>:<k>" with k running 0.. (player.json: "<tag>:<sheet index>")
    RblAtlas ase = RblLoadAtlas(SHARED_ATLASES "aseprite/frames.json");
    int tagBad = 0;
    for (int t = 0; RblIsAtlasValid(&ase) && t < ase.tagCount; t++)
        for (int f = ase.tags[t].from; f <= ase.tags[t].to; f++)
        {
            char want[96]; snprintf(want, sizeof(want), "%s:%d", ase.tags[t].name, f - ase.tags[t].from);
            if (strcmp(ase.frames[f].name, want) != 0) tagBad++;
        }
    RT_CHECK(RblIsAtlasValid(&ase) && ase.tagCount == 11 && tagBad == 0, "frames.json: %d tag frames misplaced", tagBad);
    RblUnloadAtlas(&ase);
    ase = RblLoadAtlas(SHARED_ATLASES "aseprite/player.json");
    tagBad = 0;
    for (int t = 0; RblIsAtlasValid(&ase) && t < ase.tagCount; t++)
        for (int f = ase.tags[t].from; f <= ase.tags[t].to; f++)
        {
            char want[96]; snprintf(want, sizeof(want), "%s:%d", ase.tags[t].name, f);
            if (strcmp(ase.frames[f].name, want) != 0) tagBad++;
        }
    int climb = RblAtlasFindTag(&ase, "climb");
    RT_CHECK(RblIsAtlasValid(&ase) && ase.tagCount == 18 && tagBad == 0 && climb >= 0 && ase.tags[climb].repeat == 2 && ase.frames[0].duration == 0.25f, "player.json: %d misplaced, climb repeat", tagBad);
    RblUnloadAtlas(&ase);

    // Format meaning, libGDX: the turned frames of libgdx-packed (one animation on 120x175 canvases)
    // rebuilt counter-clockwise match the upright frame 0000 better than half-turned
    RblAtlas gdx = RblLoadAtlas(SHARED_ATLASES "libgdx/libgdx-packed.atlas");
    Image gs = LoadImage(SHARED_ATLASES "libgdx/libgdx-packed.png");
    if (RblIsAtlasValid(&gdx) && gs.data)
    {
        ImageFormat(&gs, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
        Image ref = frameCanvas(gs, &gdx.frames[0], true, false);
        for (int f = 1; f < gdx.frameCount; f++)
        {
            if (!(gdx.frames[f].flags & RBL_FRAME_ROTATED)) continue;
            Image r = frameCanvas(gs, &gdx.frames[f], true, false), w = frameCanvas(gs, &gdx.frames[f], true, true);
            double right = meanAbsDiff(r, ref), wrong = meanAbsDiff(w, ref);
            printf("    libgdx %s vs 0000: mean |diff| %.2f/255 (half-turned: %.2f)\n", gdx.frames[f].name, right, wrong);
            RT_CHECK(right < wrong, "libgdx %s: counter-clockwise %.2f not below half-turned %.2f", gdx.frames[f].name, right, wrong);
            UnloadImage(r); UnloadImage(w);
        }
        UnloadImage(ref);
    }
    else RT_CHECK(false, "libgdx-packed");
    UnloadImage(gs);
    RblUnloadAtlas(&gdx);
}
