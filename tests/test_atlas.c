// Sprite-sheet atlases (TexturePacker, Aseprite, libGDX), animation playback and N-way sectors.
// Hand-written fixtures (tests/fuzz/corpus/, also the fuzz seeds; loaded from the copies
// rtAtlasFixtures puts beside generated sheets under build/tests/atlas/) with expectations derived by hand
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

// A fixture's path under build/tests/atlas/ (copied beside its sheets by rtAtlasFixtures)
static const char *atlasFixture(const char *name)
{
    static char paths[4][256];
    static int next = 0;
    const char *dir = rtAtlasFixtures();
    char *p = paths[next++ & 3];
    snprintf(p, sizeof(paths[0]), "%s/%s", (dir != NULL)? dir : "(no fixtures)", name);
    return p;
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
    const char *files[2] = { "texturepacker/hash.json", "texturepacker/array.json" };
    for (int k = 0; k < 2; k++)
    {
        RblAtlas a = RblLoadAtlas(atlasFixture(files[k]));
        RT_CHECK(RblIsAtlasValid(a) && (a.format == RBL_ATLAS_TEXTUREPACKER) && (a.frameCount == 3) && (a.pageCount == 1) && (a.tagCount == 0), "%s: valid %d format %d frames %d", files[k], RblIsAtlasValid(a), a.format, a.frameCount);
        if (a.frameCount != 3) { RblUnloadAtlas(&a); continue; }
        RT_CHECK(strcmp(a.pages[0].image, "build/tests/atlas/texturepacker/sheet.png") == 0 && a.pages[0].scale == 1.0f && a.pages[0].normalImage == NULL && !a.pages[0].premultiplied && a.pages[0].width == 128 && a.pages[0].height == 64, "%s: page %s %dx%d", files[k], a.pages[0].image, a.pages[0].width, a.pages[0].height);
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
        // no pivot given: the bottom centre (10, 10) px; the quad's bottom-left is (0, 10): origin (10, 0)
        RT_CHECK(f->pivot.x == 0.5f && f->pivot.y == 1.0f, "b: default pivot %g %g, expected the bottom centre", f->pivot.x, f->pivot.y);
        checkQuad(&a, 1, 1.0f, 20.0f, 10.0f, 10.0f, 0.0f, "b at 1");
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
    RblAtlas a = RblLoadAtlas(atlasFixture("texturepacker/multi-0.json"));
    RT_CHECK(RblIsAtlasValid(a) && a.pageCount == 2 && a.frameCount == 2, "pages %d frames %d", a.pageCount, a.frameCount);
    if (a.pageCount == 2 && a.frameCount == 2)
    {
        RT_CHECK(strcmp(a.pages[1].image, "build/tests/atlas/texturepacker/multi-1.png") == 0 && a.frames[0].page == 0 && a.frames[1].page == 1, "page of each frame");
        CHECK_RECT(a.frames[1].block, 4, 0, 12, 4, "two block (rotated 4x12)");
    }
    RblUnloadAtlas(&a);
    // a related pack named outside the atlas's folder is refused (one line), nothing else read
    SaveFileText("build/tests/atlas_related_escape.json", (char *)"{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"related_multi_packs\": [\"../atlas.json\"]}}");
    SetTraceLogCallback(atlasCountingLog);
    atlasWarnings = 0;
    a = RblLoadAtlas("build/tests/atlas_related_escape.json");
    RT_CHECK(!RblIsAtlasValid(a) && atlasWarnings == 1, "related pack outside the folder: valid %d, %d lines", RblIsAtlasValid(a), atlasWarnings);
    SetTraceLogCallback(NULL);
    // from memory nothing else is read: one sheet
    int size = 0;
    unsigned char *text = LoadFileData("tests/fuzz/corpus/texturepacker/multi-0.json", &size);
    a = RblLoadAtlasFromMemory((const char *)text, size, RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(a) && a.pageCount == 1 && a.frameCount == 1, "from memory: pages %d", a.pageCount);
    RblUnloadAtlas(&a);
    UnloadFileData(text);
}

static void test_atlas_aseprite_durations_tags_and_slice_pivots(void)
{
    RblAtlas a = RblLoadAtlas(atlasFixture("aseprite/tags.json"));
    RT_CHECK(RblIsAtlasValid(a) && a.format == RBL_ATLAS_ASEPRITE && a.frameCount == 4 && a.tagCount == 4 && a.sliceCount == 3, "format %d frames %d tags %d slices %d", a.format, a.frameCount, a.tagCount, a.sliceCount);
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
    RblAtlas a = RblLoadAtlas(atlasFixture("libgdx/old.atlas"));
    RT_CHECK(RblIsAtlasValid(a) && a.format == RBL_ATLAS_LIBGDX && a.frameCount == 3 && a.tagCount == 1 && a.pageCount == 1, "old: frames %d tags %d", a.frameCount, a.tagCount);
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
        // libGDX states no pivot: the bottom centre (8, 16) of 16x16; quad bottom-left at (3, 15): origin (5, -1)
        checkQuad(&a, 1, 1.0f, 8.0f, 12.0f, 5.0f, -1.0f, "run1");
    }
    RblUnloadAtlas(&a);
    a = RblLoadAtlas(atlasFixture("libgdx/new.atlas"));
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 3 && a.pageCount == 2 && a.tagCount == 0, "new: frames %d pages %d", a.frameCount, a.pageCount);
    if (a.frameCount == 3 && a.pageCount == 2)
    {
        RT_CHECK(a.pages[0].width == 64 && a.pages[0].height == 32 && a.pages[1].width == 8 && strcmp(a.pages[1].image, "build/tests/atlas/libgdx/second.png") == 0, "new: pages");
        RT_CHECK(a.pages[0].premultiplied && !a.pages[1].premultiplied, "new: pma:true on the first page only");
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
    RblAtlas a = RblLoadAtlas(atlasFixture("texturepacker/hash.json"));
    if (!RblIsAtlasValid(a)) { RT_CHECK(false, "fixture"); return; }
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
    RblAtlas a = RblLoadAtlas(atlasFixture("aseprite/tags.json"));
    if (!RblIsAtlasValid(a)) { RT_CHECK(false, "fixture"); return; }
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
    // RblAtlasBillboardFade of that pair: the weight and the next frame's rotation (its source over the
    // union of the two trims: test_fade.c)
    RblFade fade;
    RblBillboard fadeCard;
    memset(&fade, 0, sizeof(fade));
    memset(&fadeCard, 0, sizeof(fadeCard));
    bool faded = RblAtlasBillboardFade(&a, p.frame, next, w, 1.0f, &fadeCard, &fade);
    RT_CHECK(faded && fade.weight == 0.5f && fade.flags == (a.frames[2].flags & RBL_FRAME_ROTATED), "fade: %d, weight %g", faded, fade.weight);
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
    RblAtlas a = RblLoadAtlas(atlasFixture("aseprite/tags.json"));
    if (!RblIsAtlasValid(a)) { RT_CHECK(false, "fixture"); return; }
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
        RT_CHECK(!RblIsAtlasValid(a) && a.state == NULL && a.frameCount == 0 && atlasWarnings == 1, "input %d (%.40s): valid %d, %d lines", i, bad[i], RblIsAtlasValid(a), atlasWarnings);
        RblUnloadAtlas(&a);
    }
    // nesting past the limit
    char deep[300];
    memset(deep, '[', sizeof(deep));
    atlasWarnings = 0;
    RblAtlas a = RblLoadAtlasFromMemory(deep, (int)sizeof(deep), RBL_ATLAS_TEXTUREPACKER);
    RT_CHECK(!RblIsAtlasValid(a) && atlasWarnings == 1, "deep nesting: %d lines", atlasWarnings);
    // every truncation of the valid fixtures fails cleanly (or parses a shorter valid text)
    const char *files[8] = { "tests/fuzz/corpus/texturepacker/hash.json", "tests/fuzz/corpus/aseprite/tags.json", "tests/fuzz/corpus/libgdx/old.atlas", "tests/fuzz/corpus/libgdx/new.atlas",
                             "tests/fuzz/corpus/texturepacker/phaser3.json", "tests/fuzz/corpus/texturepacker/polygon.json", "tests/fuzz/corpus/aseprite/slices.json", "tests/fuzz/corpus/libgdx/rotations.atlas" };
    int wrongLines = 0;
    for (int f = 0; f < 8; f++)
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
            if (RblIsAtlasValid(a)) { if (atlasWarnings != 0) wrongLines++; RblUnloadAtlas(&a); }
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

#define SHARED_ATLASES "../shared/atlases/"

// ---- what each exporter states beyond rectangles (issue #28) ---------------------------------------
// Deterministic opaque noise (CPU checks of which texel lands where)
static Image noiseSheetCpu(int w, int h, unsigned int seed)
{
    Image img = GenImageColor(w, h, BLANK);
    Color *px = (Color *)img.data;
    for (int i = 0; i < w*h; i++) { unsigned int r = rtRandom(&seed); px[i] = (Color){ (unsigned char)r, (unsigned char)(r >> 8), (unsigned char)(r >> 16), 255 }; }
    return img;
}

// Every "RBL:" line with its level, for the tests that read the line or count INFO lines
static int atlasInfoLines = 0, atlasWarnLines = 0;
static char atlasLastLine[4096];
static void atlasLevelLog(int level, const char *text, va_list args)
{
    char line[4096];
    vsnprintf(line, sizeof(line), text, args);
    if (strncmp(line, "RBL:", 4) != 0) return;
    if (level == LOG_INFO) atlasInfoLines++;
    else if (level >= LOG_WARNING) { atlasWarnLines++; memcpy(atlasLastLine, line, sizeof(line)); }
}
static void atlasLogBegin(void) { atlasInfoLines = 0; atlasWarnLines = 0; atlasLastLine[0] = 0; SetTraceLogLevel(LOG_INFO); SetTraceLogCallback(atlasLevelLog); }
static void atlasLogEnd(void) { SetTraceLogCallback(NULL); SetTraceLogLevel(LOG_WARNING); }

static RblAtlas atlasFromText(const char *text) { return RblLoadAtlasFromMemory(text, (int)strlen(text), RBL_ATLAS_AUTO); }

static void test_atlas_phaser3_textures_are_one_page_each_with_its_normal_sheet_and_scale(void)
{
    RblAtlas a = RblLoadAtlas(atlasFixture("texturepacker/phaser3.json"));
    RT_CHECK(RblIsAtlasValid(a) && a.format == RBL_ATLAS_TEXTUREPACKER && a.pageCount == 2 && a.frameCount == 3, "valid %d format %d pages %d frames %d", RblIsAtlasValid(a), a.format, a.pageCount, a.frameCount);
    if (a.pageCount != 2 || a.frameCount != 3) { RblUnloadAtlas(&a); return; }
    // page 0 names its normal sheet (normalMap) and scale 0.5; page 1 neither: its "_n" sheet beside
    // it is found by the convention, its scale is meta's "1"
    const RblAtlasPage *p0 = &a.pages[0], *p1 = &a.pages[1];
    RT_CHECK(strcmp(p0->image, "build/tests/atlas/texturepacker/phaser-0.png") == 0 && p0->normalImage != NULL && strcmp(p0->normalImage, "build/tests/atlas/texturepacker/phaser-0_n.png") == 0 &&
             p0->width == 64 && p0->height == 32 && p0->scale == 0.5f && !p0->premultiplied, "page 0: %s / %s %dx%d scale %g", p0->image, p0->normalImage ? p0->normalImage : "(none)", p0->width, p0->height, p0->scale);
    RT_CHECK(strcmp(p1->image, "build/tests/atlas/texturepacker/phaser-1.png") == 0 && p1->normalImage != NULL && strcmp(p1->normalImage, "build/tests/atlas/texturepacker/phaser-1_n.png") == 0 &&
             p1->width == 32 && p1->scale == 1.0f, "page 1: %s / %s scale %g", p1->image, p1->normalImage ? p1->normalImage : "(none)", p1->scale);
    // knight: trimmed 20x28 at (2,4) of 24x32, no pivot (bottom centre 12, 32); a texel is 2 world
    // units at worldScale 1 (scale 0.5): size 40x56, origin ((12 - 2)2, (4 + 28 - 32)2) = (20, 0)
    int knight = RblAtlasFindFrame(&a, "knight"), panel = RblAtlasFindFrame(&a, "panel"), gem = RblAtlasFindFrame(&a, "gem");
    RT_CHECK(knight == 0 && panel == 1 && gem == 2 && a.frames[0].page == 0 && a.frames[1].page == 0 && a.frames[2].page == 1, "frames on their pages");
    CHECK_RECT(a.frames[0].block, 0, 0, 20, 28, "knight block"); CHECK_RECT(a.frames[0].trim, 2, 4, 20, 28, "knight trim");
    checkQuad(&a, 0, 1.0f, 40.0f, 56.0f, 20.0f, 0.0f, "knight at scale 0.5");
    // panel: turned clockwise in an 8x16 block, anchor centre (8, 4): size 32x16, origin (16, 8);
    // scale9Borders: the 9-slice centre (3, 2) 10x4 in frame pixels
    CHECK_RECT(a.frames[1].block, 24, 0, 8, 16, "panel block"); CHECK_RECT(a.frames[1].center, 3, 2, 10, 4, "panel 9-slice centre");
    RT_CHECK(a.frames[1].flags == RBL_FRAME_ROTATED, "panel rotated");
    checkQuad(&a, 1, 1.0f, 32.0f, 16.0f, 16.0f, 8.0f, "panel at scale 0.5");
    checkQuad(&a, 2, 1.0f, 8.0f, 8.0f, 4.0f, 0.0f, "gem at scale 1");
    CHECK_RECT(a.frames[2].center, 0, 0, 0, 0, "gem: no 9-slice");
    RblUnloadAtlas(&a);
    // from memory: the names as written, nothing probed (no file system is assumed)
    int size = 0;
    unsigned char *text = LoadFileData("tests/fuzz/corpus/texturepacker/phaser3.json", &size);
    a = RblLoadAtlasFromMemory((const char *)text, size, RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(a) && a.pageCount == 2 && strcmp(a.pages[0].image, "phaser-0.png") == 0 && strcmp(a.pages[0].normalImage, "phaser-0_n.png") == 0 && a.pages[1].normalImage == NULL,
             "from memory: pages as written");
    RblUnloadAtlas(&a);
    UnloadFileData(text);
    // malformed multi-texture files: one line each
    static const char *bad[] = {
        "{\"textures\": []}", "{\"textures\": {}}", "{\"textures\": [{\"image\": \"a.png\"}]}",
        "{\"textures\": [{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"normalMap\": 5}]}",
        "{\"textures\": [{\"frames\": []}], \"frames\": []}",
        "{\"textures\": [{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"scale\": 0}]}",
        "{\"textures\": [{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}, \"scale9Borders\": {\"x\":1,\"y\":1,\"w\":4,\"h\":1}}]}]}" };
    atlasLogBegin();
    for (int i = 0; i < (int)(sizeof(bad)/sizeof(bad[0])); i++)
    {
        atlasWarnLines = 0;
        a = atlasFromText(bad[i]);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "bad multi-texture %d: valid %d, %d lines (%s)", i, RblIsAtlasValid(a), atlasWarnLines, atlasLastLine);
    }
    atlasLogEnd();
}

static void test_atlas_sheet_paths_resolve_as_written_then_beside_then_by_the_atlas_name(void)
{
    // As written, joined to the atlas's folder: hash.json's sheet.png. Beside the atlas by base name:
    // polygon.json's absolute Windows path, slices.json's "examples/slices.png"
    RblAtlas a = RblLoadAtlas(atlasFixture("texturepacker/polygon.json")), b = RblLoadAtlas(atlasFixture("aseprite/slices.json"));
    RT_CHECK(RblIsAtlasValid(a) && strcmp(a.pages[0].image, "build/tests/atlas/texturepacker/poly.png") == 0, "Windows path: %s", RblIsAtlasValid(a)? a.pages[0].image : "(refused)");
    RT_CHECK(RblIsAtlasValid(b) && strcmp(b.pages[0].image, "build/tests/atlas/aseprite/slices.png") == 0, "other folder: %s", RblIsAtlasValid(b)? b.pages[0].image : "(refused)");
    RblUnloadAtlas(&a); RblUnloadAtlas(&b);
    // By the atlas's own name: "export.png" does not exist, renamed.png does (as test-trim-rotation)
    MakeDirectory("build/tests/atlas_paths");
    Image sheet = GenImageColor(8, 8, RED);
    ExportImage(sheet, "build/tests/atlas_paths/renamed.png");
    ExportImage(sheet, "build/tests/atlas_paths/renamed_n.png");
    UnloadImage(sheet);
    const char *json = "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"image\": \"export.png\", \"size\": {\"w\":8,\"h\":8}}}";
    SaveFileText("build/tests/atlas_paths/renamed.json", (char *)json);
    a = RblLoadAtlas("build/tests/atlas_paths/renamed.json");
    RT_CHECK(RblIsAtlasValid(a) && strcmp(a.pages[0].image, "build/tests/atlas_paths/renamed.png") == 0 && a.pages[0].normalImage != NULL &&
             strcmp(a.pages[0].normalImage, "build/tests/atlas_paths/renamed_n.png") == 0, "by the atlas's name: %s", RblIsAtlasValid(a)? a.pages[0].image : "(refused)");
    RblUnloadAtlas(&a);
    // Found nowhere: one line naming every path tried, in order
    json = "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"image\": \"art/missing.png\"}}";
    SaveFileText("build/tests/atlas_paths/lost.json", (char *)json);
    atlasLogBegin();
    a = RblLoadAtlas("build/tests/atlas_paths/lost.json");
    RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "missing sheet: valid %d, %d lines", RblIsAtlasValid(a), atlasWarnLines);
    const char *tried[3] = { "\"build/tests/atlas_paths/art/missing.png\"", "\"build/tests/atlas_paths/missing.png\"", "\"build/tests/atlas_paths/lost.png\"" };
    const char *at[3];
    for (int k = 0; k < 3; k++) at[k] = strstr(atlasLastLine, tried[k]);
    RT_CHECK(at[0] != NULL && at[1] > at[0] && at[2] > at[1], "the line names the three paths in order: %s", atlasLastLine);
    // a named normal sheet: as written, beside by its base name, then the colour sheet's "_n" name
    // (renamed_n.png here); found nowhere, refused the same way
    json = "{\"textures\": [{\"image\": \"renamed.png\", \"normalMap\": \"maps/bump.png\", \"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}]}]}";
    SaveFileText("build/tests/atlas_paths/bumpless.json", (char *)json);
    atlasWarnLines = 0;
    a = RblLoadAtlas("build/tests/atlas_paths/bumpless.json");
    RT_CHECK(RblIsAtlasValid(a) && atlasWarnLines == 0 && strcmp(a.pages[0].normalImage, "build/tests/atlas_paths/renamed_n.png") == 0, "normal sheet by the colour sheet's name: %s", atlasLastLine);
    RblUnloadAtlas(&a);
    remove("build/tests/atlas_paths/renamed_n.png");
    a = RblLoadAtlas("build/tests/atlas_paths/bumpless.json");
    RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1 && strstr(atlasLastLine, "normal sheet \"maps/bump.png\" not found") != NULL && strstr(atlasLastLine, "\"build/tests/atlas_paths/maps/bump.png\"") != NULL &&
             strstr(atlasLastLine, "\"build/tests/atlas_paths/bump.png\"") != NULL && strstr(atlasLastLine, "\"build/tests/atlas_paths/renamed_n.png\"") != NULL, "missing normal sheet: %s", atlasLastLine);
    // libGDX pages likewise
    SaveFileText("build/tests/atlas_paths/gdx.atlas", (char *)"\nnowhere.png\nr\n  xy: 0, 0\n  size: 4, 4\n");
    atlasWarnLines = 0;
    a = RblLoadAtlas("build/tests/atlas_paths/gdx.atlas");
    RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1 && strstr(atlasLastLine, "\"build/tests/atlas_paths/nowhere.png\"") && strstr(atlasLastLine, "\"build/tests/atlas_paths/gdx.png\""), "libGDX: %s", atlasLastLine);
    atlasLogEnd();
    // the real exporter files: test-trim-rotation.json says test.png (found by the json's name),
    // building1.json's sheet is as written
    if (DirectoryExists(SHARED_ATLASES))
    {
        a = RblLoadAtlas(SHARED_ATLASES "texturepacker/test-trim-rotation.json");
        RT_CHECK(RblIsAtlasValid(a) && strcmp(a.pages[0].image, SHARED_ATLASES "texturepacker/test-trim-rotation.png") == 0, "test-trim-rotation: %s", RblIsAtlasValid(a)? a.pages[0].image : "(refused)");
        RblUnloadAtlas(&a);
    }
}

static void test_atlas_meta_scale_as_string_or_number_draws_every_export_at_one_world_size(void)
{
    // One 32x32 sprite trimmed to (8, 4) 16x24, pivot (0.5, 1), exported at 1, "0.5" and 0.25
    static const char fmt[] = "{\"frames\": {\"s\": {\"frame\": {\"x\":0,\"y\":0,\"w\":%d,\"h\":%d}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":%d,\"y\":%d,\"w\":%d,\"h\":%d},"
                              " \"sourceSize\": {\"w\":%d,\"h\":%d}, \"pivot\": {\"x\":0.5,\"y\":1}}}, \"meta\": {\"scale\": %s}}";
    const char *scales[3] = { "1", "\"0.5\"", "0.25" };
    const int div[3] = { 1, 2, 4 };
    RblBillboard b[3];
    for (int i = 0; i < 3; i++)
    {
        char text[512];
        int d = div[i];
        snprintf(text, sizeof(text), fmt, 16/d, 24/d, 8/d, 4/d, 16/d, 24/d, 32/d, 32/d, scales[i]);
        RblAtlas a = atlasFromText(text);
        memset(&b[i], 0, sizeof(b[i]));
        RT_CHECK(RblIsAtlasValid(a) && a.pages[0].scale == 1.0f/d && RblAtlasBillboard(&a, 0, 1.0f/32.0f, &b[i]), "scale %s: page scale %g", scales[i], RblIsAtlasValid(a)? a.pages[0].scale : 0.0f);
        RblUnloadAtlas(&a);
    }
    // 32 px per unit at scale 1: 0.5 x 0.75 units; the pivot (16, 32) lies 8 px right of the trim's
    // left (0.25) and 4 px below its bottom (28): origin (0.25, -0.125)
    for (int i = 0; i < 3; i++)
        RT_CHECK(b[i].size.x == 0.5f && b[i].size.y == 0.75f && b[i].origin.x == 0.25f && b[i].origin.y == -0.125f, "scale %s: size %g %g origin %g %g", scales[i], b[i].size.x, b[i].size.y, b[i].origin.x, b[i].origin.y);
    // the real pair: building1 (scale "0.5") and building1-0 (scale 1) show their stars at one size
    if (DirectoryExists(SHARED_ATLASES))
    {
        RblAtlas half = RblLoadAtlas(SHARED_ATLASES "texturepacker/building1.json"), full = RblLoadAtlas(SHARED_ATLASES "texturepacker/building1-0.json");
        RT_CHECK(RblIsAtlasValid(half) && RblIsAtlasValid(full) && half.pages[0].scale == 0.5f && full.pages[0].scale == 1.0f, "building1 scales");
        for (int s = 1; s <= 4 && RblIsAtlasValid(half) && RblIsAtlasValid(full); s++)
        {
            char name[32]; snprintf(name, sizeof(name), "star%d.png", s);
            const RblAtlasFrame *fh = &half.frames[RblAtlasFindFrame(&half, name)], *ff = &full.frames[RblAtlasFindFrame(&full, name)];
            double worldH = fh->size.x/half.pages[0].scale, worldF = ff->size.x/full.pages[0].scale;
            RT_CHECK(worldH == worldF, "%s: canvas %g px at 0.5 vs %g px at 1", name, worldH, worldF);
        }
        RblUnloadAtlas(&half); RblUnloadAtlas(&full);
    }
    // scales that cannot be one: one line each
    const char *badScales[6] = { "0", "-1", "\"abc\"", "1e9", "\"1e-9\"", "null" };
    atlasLogBegin();
    for (int i = 0; i < 6; i++)
    {
        char text[512];
        snprintf(text, sizeof(text), fmt, 16, 24, 8, 4, 16, 24, 32, 32, badScales[i]);
        atlasWarnLines = 0;
        RblAtlas a = atlasFromText(text);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1 && strstr(atlasLastLine, "scale") != NULL, "scale %s: valid %d, %d lines (%s)", badScales[i], RblIsAtlasValid(a), atlasWarnLines, atlasLastLine);
    }
    atlasLogEnd();
}

static void test_atlas_zero_negative_fractional_or_non_finite_page_sizes_are_refused(void)
{
    static const char fmt[] = "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"size\": {\"w\":%s,\"h\":%s}}}";
    const char *sizes[][2] = { { "64", "0" }, { "64", "-0" }, { "64", "0.5" }, { "64", "1e-400" }, { "-64", "64" }, { "64", "1e999" }, { "64.5", "64" }, { "0", "0" }, { "\"64\"", "\"x\"" } };
    atlasLogBegin();
    for (int i = 0; i < (int)(sizeof(sizes)/sizeof(sizes[0])); i++)
    {
        char text[256];
        snprintf(text, sizeof(text), fmt, sizes[i][0], sizes[i][1]);
        atlasWarnLines = 0;
        RblAtlas a = atlasFromText(text);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "size %s x %s: valid %d, %d lines (%s)", sizes[i][0], sizes[i][1], RblIsAtlasValid(a), atlasWarnLines, atlasLastLine);
    }
    // the same for a Phaser 3 texture and for libGDX pages
    const char *others[] = { "{\"textures\": [{\"size\": {\"w\":8,\"h\":0}, \"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}]}]}",
                             "p.png\nsize: 64, 0\nr\n  xy: 0, 0\n  size: 4, 4\n", "p.png\nsize: 64, 1.5\nr\n  xy: 0, 0\n  size: 4, 4\n", "p.png\nsize: -64, 64\nr\n  xy: 0, 0\n  size: 4, 4\n" };
    for (int i = 0; i < 4; i++)
    {
        atlasWarnLines = 0;
        RblAtlas a = atlasFromText(others[i]);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "page size %d: valid %d, %d lines (%s)", i, RblIsAtlasValid(a), atlasWarnLines, atlasLastLine);
    }
    atlasLogEnd();
    // whole sizes are kept; a frame beyond them is refused (the check the bad sizes used to skip)
    RblAtlas a = atlasFromText("{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"size\": {\"w\":4,\"h\":1e0}}}");
    RT_CHECK(!RblIsAtlasValid(a), "a 4x4 frame on a 4x1 sheet accepted");
    a = atlasFromText("{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"size\": {\"w\":4,\"h\":4.0}}}");
    RT_CHECK(RblIsAtlasValid(a) && a.pages[0].height == 4, "4.0 is a whole size");
    RblUnloadAtlas(&a);
}

// Twice the signed area of triangle (a, b, c)
static double triArea2(Vector2 a, Vector2 b, Vector2 c) { return ((double)b.x - a.x)*((double)c.y - a.y) - ((double)c.x - a.x)*((double)b.y - a.y); }

static void test_atlas_polygon_frames_keep_their_vertices_uvs_and_triangles_validated(void)
{
    RblAtlas a = RblLoadAtlas(atlasFixture("texturepacker/polygon.json"));
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 2 && a.pages[0].scale == 0.5f, "fixture");
    if (!RblIsAtlasValid(a) || a.frameCount != 2) { RblUnloadAtlas(&a); return; }
    // "tri": the trim (4,6) 12x8 with its top-left corner cut off: a pentagon, fanned from vertex 0;
    // each vertex's texel is the block's (10,20) plus its offset in the trim
    const RblAtlasPolygon *p = a.frames[0].polygon;
    static const float tv[5][2] = { { 4, 14 }, { 4, 8 }, { 8, 6 }, { 16, 6 }, { 16, 14 } }, tuv[5][2] = { { 10, 28 }, { 10, 22 }, { 14, 20 }, { 22, 20 }, { 22, 28 } };
    static const unsigned short tidx[9] = { 0, 1, 2, 0, 2, 3, 0, 3, 4 };
    RT_CHECK(p != NULL && p->vertexCount == 5 && p->indexCount == 9, "tri: polygon %p", (const void *)p);
    int bad = 0;
    for (int i = 0; p != NULL && i < 5; i++)
    {
        bad += (p->vertices[i].x != tv[i][0]) || (p->vertices[i].y != tv[i][1]) || (p->uvs[i].x != tuv[i][0]) || (p->uvs[i].y != tuv[i][1]);
        // the stated texel is the frame's own mapping of the vertex (upright: block + vertex - trim offset)
        bad += (p->uvs[i].x != a.frames[0].block.x + p->vertices[i].x - a.frames[0].trim.x) || (p->uvs[i].y != a.frames[0].block.y + p->vertices[i].y - a.frames[0].trim.y);
    }
    for (int i = 0; p != NULL && i < 9; i++) bad += p->indices[i] != tidx[i];
    RT_CHECK(bad == 0, "tri: %d values differ from the file", bad);
    // area: the trim's 96 px less the cut corner's 4 = 92, every triangle wound the same way
    double area = 0.0; int cw = 0, ccw = 0;
    for (int t = 0; p != NULL && t < p->indexCount/3; t++)
    {
        double a2 = triArea2(p->vertices[p->indices[3*t]], p->vertices[p->indices[3*t + 1]], p->vertices[p->indices[3*t + 2]]);
        area += fabs(a2)/2.0; cw += a2 < 0.0; ccw += a2 > 0.0;
    }
    RT_CHECK(area == 92.0 && (cw == 0 || ccw == 0), "tri: area %g (expected 92), windings %d/%d", area, cw, ccw);
    // "rot": flat arrays; the frame is stored turned clockwise in the 8x16 block at (40, 0): upright
    // (x, y) lies at texel (40 + 8 - y, x)
    p = a.frames[1].polygon;
    RT_CHECK(p != NULL && p->vertexCount == 3 && p->indexCount == 3 && (a.frames[1].flags & ~(unsigned int)RBL_FRAME_POLYGON) == RBL_FRAME_ROTATED, "rot: polygon");
    RT_CHECK((a.frames[0].flags & RBL_FRAME_POLYGON) != 0 && (a.frames[1].flags & RBL_FRAME_POLYGON) != 0 && (a.frames[0].flags & RBL_FRAME_POLYGON) != (a.frames[1].flags & RBL_FRAME_POLYGON), "polygon handles %#x %#x", a.frames[0].flags, a.frames[1].flags);
    bad = 0;
    for (int i = 0; p != NULL && i < 3; i++) bad += (p->uvs[i].x != 40.0f + 8.0f - p->vertices[i].y) || (p->uvs[i].y != p->vertices[i].x);
    RT_CHECK(p != NULL && bad == 0 && p->indices[0] == 0 && p->indices[1] == 1 && p->indices[2] == 2 && fabs(triArea2(p->vertices[0], p->vertices[1], p->vertices[2]))/2.0 == 64.0, "rot: %d texels off its mapping", bad);
    RblUnloadAtlas(&a);
    // many polygon frames: the tables grow while read and every polygon points into the final rows
    char *text = (char *)malloc(200000);
    int n = snprintf(text, 200000, "{\"frames\": {");
    for (int i = 0; i < 600; i++)
        n += snprintf(text + n, 200000 - n, "%s\"f%d\": {\"frame\": {\"x\":%d,\"y\":0,\"w\":4,\"h\":4}, \"vertices\": [0,0,4,0,4,4,0,%d], \"verticesUV\": [%d,0,%d,0,%d,4,%d,%d], \"triangles\": [0,1,2,0,2,3]}",
                      (i > 0)? "," : "", i, i*4, 4 - (i%5), i*4, i*4 + 4, i*4 + 4, i*4, 4 - (i%5));
    snprintf(text + n, 200000 - n, "}}");
    a = atlasFromText(text);
    bad = 0;
    for (int i = 0; RblIsAtlasValid(a) && i < a.frameCount; i++)
    {
        p = a.frames[i].polygon;
        bad += (p == NULL) || (p->vertexCount != 4) || (p->indexCount != 6) || (p->vertices[3].y != 4 - (i%5)) || (p->uvs[0].x != i*4) || (p->indices[5] != 3);
    }
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 600 && bad == 0, "600 polygon frames: %d wrong", bad);
    RblUnloadAtlas(&a);
    free(text);
    // what a polygon must be: one line for each way it is not
    static const char *broken[] = {
        "\"vertices\": [0,0,4,0,4,4], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,3]",            // index past the vertices
        "\"vertices\": [0,0,4,0,5,4], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,2]",            // vertex outside the frame
        "\"vertices\": [0,0,4,0,4,4], \"verticesUV\": [0,0,4,0,4,5], \"triangles\": [0,1,2]",            // texel outside the block
        "\"vertices\": [0,0,4,0,4,4,0,4], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,2]",        // counts differ
        "\"vertices\": [0,0,4,0,4,4]",                                                                // partial
        "\"vertices\": [0,0,4,0], \"verticesUV\": [0,0,4,0], \"triangles\": [0,1,1]",                    // fewer than 3 points
        "\"vertices\": [0,0,4,0,4,4], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1]",              // not triples
        "\"vertices\": [0,0,4,0,4,4], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,1.5]",          // not whole
        "\"vertices\": [[0,0],[4,0],[4]], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,2]",        // not a pair
        "\"vertices\": [0,0,4,0,4,4], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [[0,1],[1,2,0]]",   // not a triple
        "\"vertices\": [0,0,4,0,4,\"x\"], \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,2]",        // not a number
        "\"vertices\": 5, \"verticesUV\": [0,0,4,0,4,4], \"triangles\": [0,1,2]",
    };
    atlasLogBegin();
    for (int i = 0; i < (int)(sizeof(broken)/sizeof(broken[0])); i++)
    {
        char t[512];
        snprintf(t, sizeof(t), "{\"frames\": {\"a\": {\"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}, %s}}, \"meta\": {\"size\": {\"w\":8,\"h\":8}}}", broken[i]);
        atlasWarnLines = 0;
        a = atlasFromText(t);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "broken polygon %d: valid %d, %d lines (%s)", i, RblIsAtlasValid(a), atlasWarnLines, atlasLastLine);
    }
    atlasLogEnd();
}

#include "polygon_fixture.h"

// Twice the signed area of (p, q, r) projected on n
static double polyArea2On(const float *p, const float *q, const float *r, const double n[3])
{
    double u[3] = { (double)q[0] - p[0], (double)q[1] - p[1], (double)q[2] - p[2] }, v[3] = { (double)r[0] - p[0], (double)r[1] - p[1], (double)r[2] - p[2] };
    double c[3] = { u[1]*v[2] - u[2]*v[1], u[2]*v[0] - u[0]*v[2], u[0]*v[1] - u[1]*v[0] };
    return c[0]*n[0] + c[1]*n[1] + c[2]*n[2];
}

// Polygon frames as the batch draws them (RblBillboardQuads) against a double-precision reference
// built from the quad (RblBillboardVertices, itself checked against one): each vertex sits where the
// quad puts the texel the file names (sprite (s,t) from the frame fractions (a,b): upright s = a,
// t = b; stored turned s = b, t = 1 - a; a mirror flips its axis), with the quad's normal and tangent
// there (affine over the quad's triangle holding it); the triangles face as the quad does, with
// rounded normals each lies in one of the quad's two triangles (cut along its diagonal; flat ones
// keep the file's), and they cover the hand-derived area
static void test_atlas_polygon_quads_match_a_double_reference_of_the_quads_fields(void)
{
    RblAtlas a = atlasFromText(polyFixture);
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 3, "fixture");
    if (!RblIsAtlasValid(a) || a.frameCount != 3) { RblUnloadAtlas(&a); return; }
    Camera3D cam; memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 3, 4, 9 }; cam.target = (Vector3){ 0.5f, 0.2f, 0 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = 45; cam.projection = CAMERA_PERSPECTIVE;
    RblCameraFrame view = RblGetCameraFrame(cam);
    int configs = 0, badPos = 0, badFrame = 0, badTex = 0, badFace = 0, badArea = 0, badCount = 0, badSide = 0, mostQuads = 0;
    double worstPos = 0.0, worstFrame = 0.0;
    for (int k = 0; k < 3; k++)
        for (int facing = 0; facing < 4; facing++)
            for (int mirror = 0; mirror < 4; mirror++)
                for (int variant = 0; variant < 3; variant++)
                {
                    RblBillboard b; memset(&b, 0, sizeof(b));
                    RT_CHECK(RblAtlasBillboard(&a, k, 0.05f, &b), "billboard");
                    b.position = (Vector3){ 0.3f*k, 0.1f*mirror, -0.2f*facing };
                    b.facing = facing;
                    if (facing == RBL_FACING_FIXED) { b.axis = (Vector3){ 0.3f, 0.2f, 1 }; b.up = (Vector3){ 0, 1, 0.1f }; }
                    if (mirror & 1) b.size.x = -b.size.x;
                    if (mirror & 2) b.size.y = -b.size.y;
                    b.rotation = (variant == 1)? 37.0f : 0.0f;
                    b.roundness = (variant == 0)? 0.0f : 0.6f;
                    if (variant == 2) b.flags |= RBL_ROUND_CYLINDER;
                    RblVertex q[4], v[16];
                    int n = RblBillboardQuads(&view, POLY_SHEET, POLY_SHEET, &b, NULL, 0);
                    if (!RblBillboardVertices(&view, POLY_SHEET, POLY_SHEET, &b, q) || (n < 1) || (n > 16) || (RblBillboardQuads(&view, POLY_SHEET, POLY_SHEET, &b, v, 16) != n)) { badCount++; continue; }
                    if (n > mostQuads) mostQuads = n;
                    configs++;
                    const RblAtlasFrame *f = &a.frames[k];
                    const RblAtlasPolygon *poly = f->polygon;
                    bool rotated = (f->flags & RBL_FRAME_ROTATED) != 0, flipU = b.size.x < 0, flipV = b.size.y < 0;
                    double qn[3];
                    {
                        double e1[3], e3[3];
                        for (int e = 0; e < 3; e++) { e1[e] = (double)q[1].position[e] - q[0].position[e]; e3[e] = (double)q[3].position[e] - q[0].position[e]; }
                        qn[0] = e1[1]*e3[2] - e1[2]*e3[1]; qn[1] = e1[2]*e3[0] - e1[0]*e3[2]; qn[2] = e1[0]*e3[1] - e1[1]*e3[0];
                    }
                    double extent = fabs(b.size.x) + fabs(b.size.y) + 1.0, area = 0.0;
                    int tris = 0;
                    double side[16][4];
                    for (int i = 0; i < 4*n; i++)
                    {
                        // the texel is the file's vertex, or a point of a polygon edge on a frame diagonal (a cut)
                        double tu = v[i].texcoord[0]*(double)POLY_SHEET, tv = v[i].texcoord[1]*(double)POLY_SHEET;
                        double fa = (tu - f->block.x)/f->block.width, fb = (tv - f->block.y)/f->block.height;
                        int match = -1;
                        for (int j = 0; j < poly->vertexCount; j++) if ((fabs(tu - poly->uvs[j].x) < 1e-4) && (fabs(tv - poly->uvs[j].y) < 1e-4)) match = j;
                        bool onDiagonal = (fabs(fa - fb) < 1e-6) || (fabs(fa + fb - 1.0) < 1e-6);
                        if ((match < 0) && !onDiagonal) { badTex++; continue; }
                        double s = rotated? fb : fa, t = rotated? 1.0 - fa : fb;
                        if (flipU) s = 1.0 - s;
                        if (flipV) t = 1.0 - t;
                        double up = 1.0 - t;
                        side[i/4][i%4] = s - up;
                        int i1 = (s >= up)? 1 : 2, i2 = (s >= up)? 2 : 3;
                        double w0 = (s >= up)? 1.0 - s : 1.0 - up, w1 = (s >= up)? s - up : s, w2 = (s >= up)? up : up - s;
                        for (int e = 0; e < 3; e++)
                        {
                            double pr = q[0].position[e] + s*((double)q[1].position[e] - q[0].position[e]) + up*((double)q[3].position[e] - q[0].position[e]);
                            double nr = w0*q[0].normal[e] + w1*q[i1].normal[e] + w2*q[i2].normal[e];
                            double tr = w0*q[0].tangent[e] + w1*q[i1].tangent[e] + w2*q[i2].tangent[e];
                            worstPos = fmax(worstPos, fabs(v[i].position[e] - pr)/extent);
                            worstFrame = fmax(worstFrame, fmax(fabs(v[i].normal[e] - nr), fabs(v[i].tangent[e] - tr)));
                        }
                        badFrame += (v[i].tangent[3] != q[0].tangent[3]) || (memcmp(v[i].color, q[0].color, 4) != 0);
                    }
                    for (int sl = 0; sl < n; sl++)
                    {
                        const RblVertex *o = v + 4*sl;
                        for (int t = 0; t < 2; t++)
                        {
                            const RblVertex *c1 = &o[1 + t], *c2 = &o[2 + t];
                            if ((t == 1) && (memcmp(o[2].position, o[3].position, sizeof(o[2].position)) == 0) && (memcmp(o[2].texcoord, o[3].texcoord, sizeof(o[2].texcoord)) == 0)) continue;   // a lone triangle
                            tris++;
                            badFace += !(polyArea2On(o[0].position, c1->position, c2->position, qn) > 0.0);
                            // wholly in one of the quad's triangles: s - up of one sign (or zero)
                            double lo = fmin(side[sl][0], fmin(side[sl][1 + t], side[sl][2 + t])), hi = fmax(side[sl][0], fmax(side[sl][1 + t], side[sl][2 + t]));
                            badSide += (b.roundness > 0.0f) && (lo < -1e-6) && (hi > 1e-6);      // flat draws keep the file's triangles
                            double ax = o[0].texcoord[0]*(double)POLY_SHEET, ay = o[0].texcoord[1]*(double)POLY_SHEET;
                            area += fabs((c1->texcoord[0]*(double)POLY_SHEET - ax)*(c2->texcoord[1]*(double)POLY_SHEET - ay) - (c2->texcoord[0]*(double)POLY_SHEET - ax)*(c1->texcoord[1]*(double)POLY_SHEET - ay))/2.0;
                        }
                    }
                    badArea += (fabs(area - polyFixtureArea[k]) > 1e-3) || (tris < polyFixtureTriangles[k]);
                }
    badPos = worstPos > 2e-6;
    badFrame += worstFrame > 2e-6;
    RT_CHECK(configs == 144 && badCount == 0, "%d of 144 configurations emitted (%d refused or wrong count)", configs, badCount);
    RT_CHECK(badPos == 0 && badTex == 0, "positions off the quad's by %.3g of the extent; %d texels not the file's", worstPos, badTex);
    RT_CHECK(badFrame == 0, "normal/tangent off the quad's field by %.3g (or handedness/colour differ)", worstFrame);
    RT_CHECK(badFace == 0 && badArea == 0, "%d triangles face away from the quad; %d configurations with area or triangle count off", badFace, badArea);
    RT_CHECK(badSide == 0, "%d triangles cross the quad's diagonal", badSide);
    printf("      144 configurations (at most %d quads): positions within %.2g of the extent, normal/tangent within %.2g of the quad's field\n", mostQuads, worstPos, worstFrame);
    // a frame without a polygon takes the quad (one slot) and clears the bits a polygon frame left
    RblBillboard b; memset(&b, 0, sizeof(b));
    RblAtlasBillboard(&a, 0, 0.05f, &b);
    unsigned int handle = b.flags & RBL_FRAME_POLYGON;
    RblAtlas plain = atlasFromText("{\"frames\": {\"a\": {\"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}}, \"meta\": {\"size\": {\"w\":8,\"h\":8}}}");
    RblAtlasBillboard(&plain, 0, 0.05f, &b);
    RT_CHECK(handle != 0 && (b.flags & RBL_FRAME_POLYGON) == 0 && RblBillboardQuads(&view, 8, 8, &b, NULL, 0) == 1, "plain frame after a polygon frame: flags %#x", b.flags);
    RblUnloadAtlas(&plain);
    // kept past its atlas's unload, a polygon billboard is refused with one line (its handle is not reused)
    RblAtlasBillboard(&a, 2, 0.05f, &b);
    RblUnloadAtlas(&a);
    RblAtlas again = atlasFromText(polyFixture);
    atlasLogBegin();
    RblVertex v[16];
    int n = RblBillboardQuads(&view, POLY_SHEET, POLY_SHEET, &b, v, 16);
    RT_CHECK(n == -1 && atlasWarnLines == 1 && strstr(atlasLastLine, "RblBillboardQuads") != NULL, "stale polygon billboard: %d quads, %d lines (%s)", n, atlasWarnLines, atlasLastLine);
    atlasLogEnd();
    RT_CHECK(RblIsAtlasValid(again) && (again.frames[2].flags & RBL_FRAME_POLYGON) != (b.flags & RBL_FRAME_POLYGON), "reloaded atlas reuses a handle");
    RblUnloadAtlas(&again);
}

// The pixels a billboard's texture coordinates put on an upright w x h picture (nearest texel, as
// billboardMismatch), against the expected upright picture
static int quadMismatch(const RblBillboard *b, Image sheet, Image expected)
{
    RblCameraFrame view = { { 0, 0, 5 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, false };
    RblVertex v[4];
    if (!RblBillboardVertices(&view, sheet.width, sheet.height, b, v)) return -1;
    float uv[4][2];
    for (int i = 0; i < 4; i++) { uv[i][0] = v[i].texcoord[0]*(float)sheet.width; uv[i][1] = v[i].texcoord[1]*(float)sheet.height; }
    int w = expected.width, h = expected.height, bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
        {
            double s = (x + 0.5)/w, t = (y + 0.5)/h;
            double u = uv[3][0]*(1 - s)*(1 - t) + uv[2][0]*s*(1 - t) + uv[0][0]*(1 - s)*t + uv[1][0]*s*t;
            double vv = uv[3][1]*(1 - s)*(1 - t) + uv[2][1]*s*(1 - t) + uv[0][1]*(1 - s)*t + uv[1][1]*s*t;
            int tx = (int)floor(u), ty = (int)floor(vv);
            if (tx < 0 || ty < 0 || tx >= sheet.width || ty >= sheet.height) { bad++; continue; }
            Color c = GetImageColor(sheet, tx, ty), d = GetImageColor(expected, x, y);
            bad += memcmp(&c, &d, sizeof(Color)) != 0;
        }
    return bad;
}

static void test_atlas_libgdx_any_quarter_turn_colon_names_pma_split_and_pad(void)
{
    atlasLogBegin();
    RblAtlas a = RblLoadAtlas(atlasFixture("libgdx/rotations.atlas"));
    // the pad entry is reported once (LOG_INFO), nothing else is said
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 7 && a.pages[0].premultiplied && atlasWarnLines == 0 && atlasInfoLines == 1, "valid %d frames %d pma %d, %d warnings, %d info",
             RblIsAtlasValid(a), a.frameCount, RblIsAtlasValid(a) && a.pages[0].premultiplied, atlasWarnLines, atlasInfoLines);
    atlasLogEnd();
    if (!RblIsAtlasValid(a) || a.frameCount != 7) { RblUnloadAtlas(&a); return; }
    // stored turned d degrees counter-clockwise: 90 and 270 in an h x w block (ROTATED: clockwise);
    // 90 and 180 are that plus a half turn (both extents negated)
    static const struct { const char *name; float block[4], source[4]; unsigned int flags; int degrees; } want[6] = {
        { "r0", { 0, 0, 8, 4 }, { 0, 0, 8, 4 }, 0, 0 }, { "r90", { 10, 0, 4, 8 }, { 10, 0, -4, -8 }, RBL_FRAME_ROTATED, 90 },
        { "r180", { 20, 0, 8, 4 }, { 20, 0, -8, -4 }, 0, 180 }, { "r270", { 30, 0, 4, 8 }, { 30, 0, 4, 8 }, RBL_FRAME_ROTATED, 270 },
        { "rneg", { 40, 0, 4, 8 }, { 40, 0, 4, 8 }, RBL_FRAME_ROTATED, 270 }, { "big:ship", { 20, 20, 12, 10 }, { 20, 20, -12, -10 }, RBL_FRAME_ROTATED, 90 } };
    Image sheet = noiseSheetCpu(64, 64, 31u);
    for (int i = 0; i < 6; i++)
    {
        int f = RblAtlasFindFrame(&a, want[i].name);
        RT_CHECK(f >= 0, "%s not found", want[i].name);
        if (f < 0) continue;
        const RblAtlasFrame *fr = &a.frames[f];
        CHECK_RECT(fr->block, want[i].block[0], want[i].block[1], want[i].block[2], want[i].block[3], want[i].name);
        CHECK_RECT(fr->source, want[i].source[0], want[i].source[1], want[i].source[2], want[i].source[3], want[i].name);
        RT_CHECK(fr->flags == want[i].flags, "%s: flags %u", want[i].name, fr->flags);
        // the upright picture by the format's meaning: the block turned back d degrees clockwise
        Image up = ImageFromImage(sheet, fr->block);
        for (int k = 0; k < want[i].degrees/90; k++) ImageRotateCW(&up);
        RblBillboard b; memset(&b, 0, sizeof(b));
        RT_CHECK(RblAtlasBillboard(&a, f, 1.0f, &b), "%s: billboard", want[i].name);
        int bad = quadMismatch(&b, sheet, up);
        RT_CHECK(up.width == (int)fr->trim.width && up.height == (int)fr->trim.height && bad == 0, "%s: %d of %dx%d pixels differ from the block turned back", want[i].name, bad, up.width, up.height);
        UnloadImage(up);
    }
    UnloadImage(sheet);
    // "big:ship" (a colon in the name, new-form offsets): trim (1, 16 - 2 - 12) 10x12 of 14x16, the
    // bottom-centre pivot (7, 16): origin (6, -2)
    int ship = RblAtlasFindFrame(&a, "big:ship"), button = RblAtlasFindFrame(&a, "ui:button");
    RT_CHECK(ship >= 0 && button >= 0, "names with colons");
    if (ship >= 0) { CHECK_RECT(a.frames[ship].trim, 1, 2, 10, 12, "big:ship trim"); checkQuad(&a, ship, 1.0f, 10.0f, 12.0f, 6.0f, -2.0f, "big:ship"); }
    // split 3, 4, 2, 5 (left, right, top, bottom) of 12x10: the centre (3, 2) 5x3
    if (button >= 0) CHECK_RECT(a.frames[button].center, 3, 2, 5, 3, "ui:button 9-slice centre");
    RblUnloadAtlas(&a);
    // from memory, the same; no INFO line when no pad is present; rotations that are no quarter turn refused
    atlasLogBegin();
    a = RblLoadAtlas(atlasFixture("libgdx/new.atlas"));
    RT_CHECK(RblIsAtlasValid(a) && atlasInfoLines == 0, "new.atlas: %d info lines", atlasInfoLines);
    RblUnloadAtlas(&a);
    const char *badRot[3] = { "p.png\nr\n  rotate: 91\n  xy: 0,0\n  size: 4,4\n", "p.png\nr\n  rotate: yes\n  xy: 0,0\n  size: 4,4\n", "p.png\nr\n  split: 3, 3, 0, 0\n  xy: 0,0\n  size: 4,4\n" };
    for (int i = 0; i < 3; i++)
    {
        atlasWarnLines = 0;
        a = atlasFromText(badRot[i]);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "bad libGDX %d: valid %d, %d lines (%s)", i, RblIsAtlasValid(a), atlasWarnLines, atlasLastLine);
    }
    // old form: an indented unknown field is still a field; an unindented colon line is a name
    atlasWarnLines = 0;
    a = atlasFromText("p.png\nsize: 8, 8\nhud:icon\n  rotate: 180\n  xy: 0, 0\n  size: 4, 2\n  custom: 1, 2\n");
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 1 && strcmp(a.frames[0].name, "hud:icon") == 0 && a.frames[0].source.width == -4.0f && a.frames[0].source.height == -2.0f && atlasWarnLines == 0,
             "old form with a colon name: valid %d (%s)", RblIsAtlasValid(a), atlasLastLine);
    RblUnloadAtlas(&a);
    // fields libGDX does not write are still fields when no region field follows them (a page's
    // "scale: 1", a region's "custom:7"); a colon line followed by a region's field is a name
    a = atlasFromText("p.png\nsize: 8, 8\nscale: 1\nrun\n  xy: 0, 0\n  size: 4, 4\n");
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 1 && strcmp(a.frames[0].name, "run") == 0, "unknown page field read as a field");
    RblUnloadAtlas(&a);
    a = atlasFromText("p.png\nsize:8,8\na\nbounds:0,0,4,4\ncustom:7\nb:c\nbounds:4,0,4,4\n");
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 2 && strcmp(a.frames[1].name, "b:c") == 0 && a.frames[1].block.x == 4.0f, "unknown region field and a colon name");
    RblUnloadAtlas(&a);
    atlasLogEnd();
}

// Untrimmed canvas of a frame by the format's meaning (TexturePacker / Aseprite: stored clockwise)
static Image canvasOf(Image sheet, const RblAtlasFrame *f)
{
    Image up = ImageFromImage(sheet, f->block);
    if (f->flags & RBL_FRAME_ROTATED) ImageRotateCCW(&up);
    Image canvas = GenImageColor((int)f->size.x, (int)f->size.y, BLANK);
    for (int y = 0; y < up.height; y++)
        for (int x = 0; x < up.width; x++) ImageDrawPixel(&canvas, (int)f->trim.x + x, (int)f->trim.y + y, GetImageColor(up, x, y));
    UnloadImage(up);
    return canvas;
}

static void test_atlas_aseprite_slices_are_sub_frames_with_their_own_pivots(void)
{
    RblAtlas a = RblLoadAtlas(atlasFixture("aseprite/slices.json"));
    RT_CHECK(RblIsAtlasValid(a) && a.format == RBL_ATLAS_ASEPRITE && a.frameCount == 2 && a.sliceCount == 5, "valid %d frames %d slices %d", RblIsAtlasValid(a), a.frameCount, a.sliceCount);
    if (!RblIsAtlasValid(a) || a.sliceCount != 5) { RblUnloadAtlas(&a); return; }
    // two slices have pivots: neither is the frames' pivot (each keeps its own); frames stand on
    // their bottom centre
    RT_CHECK(a.frames[0].pivot.x == 0.5f && a.frames[0].pivot.y == 1.0f && a.frames[1].pivot.x == 0.5f && a.frames[1].pivot.y == 1.0f, "frame pivots moved by a slice");
    // keys in file order: head@0 (frames 0..0), head@1 (1..1), sword@0 (0..1), shadow@1 (1..1), corner@0 (0..1)
    static const struct { const char *name; int frame, last; float bounds[4], pivot[2]; bool hasPivot; float center[4]; } want[5] = {
        { "head", 0, 0, { 8, 2, 16, 12 }, { 16, 14 }, true, { 0, 0, 0, 0 } }, { "head", 1, 1, { 6, 0, 16, 12 }, { 14, 12 }, true, { 0, 0, 0, 0 } },
        { "sword", 0, 1, { 20, 10, 12, 20 }, { 22, 28 }, true, { 22, 14, 8, 12 } }, { "shadow", 1, 1, { 0, 28, 32, 4 }, { 16, 32 }, false, { 0, 0, 0, 0 } },
        { "corner", 0, 1, { 0, 0, 3, 2 }, { 1.5f, 2 }, false, { 0, 0, 0, 0 } } };
    for (int i = 0; i < 5; i++)
    {
        const RblAtlasSlice *k = &a.slices[i];
        RT_CHECK(strcmp(k->name, want[i].name) == 0 && k->frame == want[i].frame && k->lastFrame == want[i].last && k->hasPivot == want[i].hasPivot &&
                 k->pivot.x == want[i].pivot[0] && k->pivot.y == want[i].pivot[1], "key %d: %s frames %d..%d pivot %g %g", i, k->name, k->frame, k->lastFrame, k->pivot.x, k->pivot.y);
        CHECK_RECT(k->bounds, want[i].bounds[0], want[i].bounds[1], want[i].bounds[2], want[i].bounds[3], want[i].name);
        CHECK_RECT(k->center, want[i].center[0], want[i].center[1], want[i].center[2], want[i].center[3], want[i].name);
    }
    RT_CHECK(RblAtlasFindSlice(&a, "head", 0) == 0 && RblAtlasFindSlice(&a, "head", 1) == 1 && RblAtlasFindSlice(&a, "sword", 1) == 2 &&
             RblAtlasFindSlice(&a, "shadow", 0) == -1 && RblAtlasFindSlice(&a, "shadow", 1) == 3 && RblAtlasFindSlice(&a, "cape", 0) == -1, "find by name and frame");
    // sub-frames: the key's bounds clipped to the frame's trim, about the key's pivot
    static const struct { int slice, frame; float size[2], origin[2], source[4]; } quads[5] = {
        { 0, 0, { 16, 12 }, { 8, 0 }, { 4, 0, 16, 12 } },          // head: trim (4,2): block (8-4, 2-2)
        { 2, 0, { 8, 20 }, { 2, 2 }, { 16, 8, 8, 20 } },           // sword clipped at the trim's right edge (28)
        { 2, 1, { 12, 20 }, { 2, 2 }, { 52, 10, 12, 20 } },        // sword on the untrimmed frame at (32, 0)
        { 3, 1, { 32, 4 }, { 16, 0 }, { 32, 28, 32, 4 } },         // shadow: no pivot, its bottom centre
        { 4, 1, { 3, 2 }, { 1.5f, 0 }, { 32, 0, 3, 2 } } };        // corner: drawn where the frame has pixels there
    Image sheet = noiseSheetCpu(64, 32, 77u);
    for (int q = 0; q < 5; q++)
    {
        RblBillboard b; memset(&b, 0, sizeof(b));
        b.flags = RBL_ROUND_CYLINDER;
        RblInstance in; memset(&in, 0, sizeof(in));
        bool ok = RblAtlasSliceBillboard(&a, quads[q].slice, quads[q].frame, 1.0f, &b) && RblAtlasSliceInstance(&a, quads[q].slice, quads[q].frame, 1.0f, &in);
        RT_CHECK(ok && b.size.x == quads[q].size[0] && b.size.y == quads[q].size[1] && b.origin.x == quads[q].origin[0] && b.origin.y == quads[q].origin[1] && (b.flags & RBL_ROUND_CYLINDER),
                 "slice %d at frame %d: size %g %g origin %g %g", quads[q].slice, quads[q].frame, b.size.x, b.size.y, b.origin.x, b.origin.y);
        CHECK_RECT(b.source, quads[q].source[0], quads[q].source[1], quads[q].source[2], quads[q].source[3], "slice source");
        RT_CHECK(memcmp(&in.source, &b.source, sizeof(Rectangle)) == 0 && memcmp(&in.size, &b.size, sizeof(Vector2)) == 0 && memcmp(&in.origin, &b.origin, sizeof(Vector2)) == 0, "instance differs");
        // its pixels are the canvas's inside the clipped bounds
        Image canvas = canvasOf(sheet, &a.frames[quads[q].frame]);
        const Rectangle t = a.frames[quads[q].frame].trim, k = a.slices[quads[q].slice].bounds;
        float l = fmaxf(t.x, k.x), top = fmaxf(t.y, k.y);
        Image crop = ImageFromImage(canvas, (Rectangle){ l, top, b.size.x, b.size.y });
        int bad = quadMismatch(&b, sheet, crop);
        RT_CHECK(bad == 0, "slice %d at frame %d: %d pixels differ from the canvas", quads[q].slice, quads[q].frame, bad);
        UnloadImage(crop); UnloadImage(canvas);
    }
    // a world scale and the page scale apply as to frames
    RblBillboard b; memset(&b, 0, sizeof(b));
    RT_CHECK(RblAtlasSliceBillboard(&a, 2, 1, 0.5f, &b) && b.size.x == 6.0f && b.size.y == 10.0f && b.origin.x == 1.0f && b.origin.y == 1.0f, "slice at 0.5");
    // refusals: a key that does not apply at the frame, a slice outside the drawn pixels, indices
    atlasLogBegin();
    RblBillboard keep = b;
    RT_CHECK(!RblAtlasSliceBillboard(&a, 3, 0, 1.0f, &b) && !RblAtlasSliceBillboard(&a, 4, 0, 1.0f, &b) && !RblAtlasSliceBillboard(&a, 5, 0, 1.0f, &b) &&
             !RblAtlasSliceBillboard(&a, 0, 2, 1.0f, &b) && !RblAtlasSliceBillboard(&a, 0, 0, NAN, &b) && !RblAtlasSliceInstance(&a, 0, 0, 1.0f, NULL) &&
             RblAtlasFindSlice(&a, NULL, 0) == -1 && RblAtlasFindSlice(&a, "head", 7) == -1 && atlasWarnLines == 8 && memcmp(&b, &keep, sizeof(b)) == 0, "refusals: %d lines", atlasWarnLines);
    atlasLogEnd();
    UnloadImage(sheet);
    RblUnloadAtlas(&a);
    // slices on a frame stored turned (a TexturePacker sheet with Aseprite-style slices): the
    // sub-source follows the turn
    const char *json = "{\"frames\": {\"t\": {\"frame\": {\"x\":4,\"y\":2,\"w\":12,\"h\":8}, \"rotated\": true, \"trimmed\": true, \"spriteSourceSize\": {\"x\":2,\"y\":1,\"w\":12,\"h\":8}, \"sourceSize\": {\"w\":16,\"h\":10}}},"
                       " \"meta\": {\"size\": {\"w\":16,\"h\":16}, \"slices\": [{\"name\": \"eye\", \"keys\": [{\"frame\": 0, \"bounds\": {\"x\":5,\"y\":3,\"w\":6,\"h\":4}}]}]}}";
    a = atlasFromText(json);
    sheet = noiseSheetCpu(16, 16, 5u);
    memset(&b, 0, sizeof(b));
    RT_CHECK(RblIsAtlasValid(a) && RblAtlasSliceBillboard(&a, 0, 0, 1.0f, &b), "turned frame slice");
    if (RblIsAtlasValid(a))
    {
        Image canvas = canvasOf(sheet, &a.frames[0]), crop = ImageFromImage(canvas, (Rectangle){ 5, 3, 6, 4 });
        int bad = quadMismatch(&b, sheet, crop);
        RT_CHECK(bad == 0 && b.size.x == 6.0f && b.size.y == 4.0f && b.origin.x == 3.0f && b.origin.y == 0.0f, "turned frame slice: %d pixels differ, size %g %g origin %g %g", bad, b.size.x, b.size.y, b.origin.x, b.origin.y);
        UnloadImage(crop); UnloadImage(canvas);
    }
    UnloadImage(sheet);
    RblUnloadAtlas(&a);
    // the one pivoted slice of an export is the frames' pivot (tags.json's "foot": see above);
    // keys past the frames, and a center outside the bounds, are refused
    const char *bad[2] = {
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"slices\": [{\"name\": \"s\", \"keys\": [{\"frame\": 1, \"bounds\": {\"x\":0,\"y\":0,\"w\":2,\"h\":2}}]}]}}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"slices\": [{\"name\": \"s\", \"keys\": [{\"frame\": 0, \"bounds\": {\"x\":0,\"y\":0,\"w\":2,\"h\":2}, \"center\": {\"x\":1,\"y\":0,\"w\":2,\"h\":1}}]}]}}" };
    atlasLogBegin();
    for (int i = 0; i < 2; i++)
    {
        atlasWarnLines = 0;
        a = atlasFromText(bad[i]);
        RT_CHECK(!RblIsAtlasValid(a) && atlasWarnLines == 1, "bad slice %d: valid %d, %d lines", i, RblIsAtlasValid(a), atlasWarnLines);
    }
    atlasLogEnd();
}

static void test_atlas_frames_without_a_pivot_stand_on_their_position(void)
{
    // untrimmed frames of every format, no pivot in the file: origin = (width/2, 0), the feet
    const char *texts[3] = {
        "{\"frames\": {\"a\": {\"frame\": {\"x\":0,\"y\":0,\"w\":10,\"h\":6}}}}",
        "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":10,\"h\":6}, \"duration\": 100}], \"meta\": {\"app\": \"http://www.aseprite.org/\"}}",
        "p.png\nsize: 16, 16\na\n  rotate: true\n  xy: 0, 0\n  size: 10, 6\n" };
    for (int i = 0; i < 3; i++)
    {
        RblAtlas a = atlasFromText(texts[i]);
        RT_CHECK(RblIsAtlasValid(a), "text %d", i);
        if (RblIsAtlasValid(a)) checkQuad(&a, 0, 0.5f, 5.0f, 3.0f, 2.5f, 0.0f, "no pivot");
        RblUnloadAtlas(&a);
    }
}

// Straight (unpremultiplied) texel of a premultiplied one, 0..1 sRGB; the sRGB curves in double
static double straightOf(unsigned char c, unsigned char a) { return (a > 0)? fmin((double)c/a, 1.0) : 0.0; }
static double srgbLin(double s) { return (s <= 0.04045)? s/12.92 : pow((s + 0.055)/1.055, 2.4); }
static double srgbEnc(double l) { return (l <= 0.0031308)? 12.92*l : 1.055*pow(l, 1.0/2.4) - 0.055; }

static void test_atlas_premultiplied_pages_pack_mips_as_the_alpha_weighted_mean_kept_premultiplied(void)
{
    // A 4x4 premultiplied albedo (libGDX pma: sRGB value x alpha): its first mip level is, texel by
    // texel, the alpha-weighted mean of the straight colours in linear light, premultiplied again
    unsigned int seed = 99u;
    Image albedo = GenImageColor(4, 4, BLANK);
    Color *px = (Color *)albedo.data;
    static const unsigned char alphas[4] = { 0, 60, 200, 255 };
    for (int i = 0; i < 16; i++)
    {
        unsigned char a = alphas[rtRandom(&seed)%4];
        Color c = { (unsigned char)rtRandom(&seed), (unsigned char)rtRandom(&seed), (unsigned char)rtRandom(&seed), a };
        px[i] = (Color){ (unsigned char)(c.r*a/255.0 + 0.5), (unsigned char)(c.g*a/255.0 + 0.5), (unsigned char)(c.b*a/255.0 + 0.5), a };
    }
    RblMaterialSource src; memset(&src, 0, sizeof(src));
    src.albedo = albedo; src.mipmaps = true; src.premultipliedAlpha = true;
    RblPackedMaterial packed; memset(&packed, 0, sizeof(packed));
    RT_CHECK(RblPackMaterial(&src, &packed) && packed.layout.premultipliedAlpha && packed.albedo.mipmaps == 3, "pack refused or layout not premultiplied");
    if (packed.albedo.data == NULL) { UnloadImage(albedo); return; }
    const unsigned char *out = (const unsigned char *)packed.albedo.data;
    int baseDiff = memcmp(out, albedo.data, 16*4) != 0, worst = 0;
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++)
        {
            double sum[3] = { 0, 0, 0 }, alpha = 0.0;
            for (int j = 0; j < 2; j++)
                for (int i = 0; i < 2; i++)
                {
                    Color c = px[(2*y + j)*4 + 2*x + i];
                    double a = c.a/255.0;
                    sum[0] += 0.25*a*srgbLin(straightOf(c.r, c.a));
                    sum[1] += 0.25*a*srgbLin(straightOf(c.g, c.a));
                    sum[2] += 0.25*a*srgbLin(straightOf(c.b, c.a));
                    alpha += 0.25*a;
                }
            const unsigned char *got = out + 16*4 + (y*2 + x)*4;
            int wantA = (int)(alpha*255.0 + 0.5);
            worst = (abs(got[3] - wantA) > worst)? abs(got[3] - wantA) : worst;
            for (int k = 0; k < 3; k++)
            {
                int want = (int)(srgbEnc((alpha > 0.0)? sum[k]/alpha : 0.0)*wantA + 0.5);
                if (abs(got[k] - want) > worst) worst = abs(got[k] - want);
            }
        }
    RT_CHECK(baseDiff == 0 && worst <= 1, "level 0 copied %d; level 1 off the double reference by %d/255", !baseDiff, worst);
    // a straight packing of the same colours (each premultiplied texel divided back, 8-bit) holds
    // that level divided by its alpha: premultiplying it again lands within 1/255
    Image straight = ImageCopy(albedo);
    Color *sp = (Color *)straight.data;
    for (int i = 0; i < 16; i++) sp[i] = (Color){ (unsigned char)(straightOf(px[i].r, px[i].a)*255.0 + 0.5), (unsigned char)(straightOf(px[i].g, px[i].a)*255.0 + 0.5), (unsigned char)(straightOf(px[i].b, px[i].a)*255.0 + 0.5), px[i].a };
    src.albedo = straight; src.premultipliedAlpha = false;
    RblPackedMaterial plain; memset(&plain, 0, sizeof(plain));
    RT_CHECK(RblPackMaterial(&src, &plain) && !plain.layout.premultipliedAlpha, "straight pack");
    int apart = 0;
    for (int i = 16; (plain.albedo.data != NULL) && (i < 20); i++)
    {
        const unsigned char *q = (const unsigned char *)plain.albedo.data + i*4, *r = out + i*4;
        for (int k = 0; k < 3; k++) { int d = abs(r[k] - (int)(q[k]*q[3]/255.0 + 0.5)); if (d > apart) apart = d; }
        apart = (abs(r[3] - q[3]) > apart)? abs(r[3] - q[3]) : apart;
    }
    RT_CHECK(apart <= 1, "premultiplied level 1 and the straight one premultiplied differ by %d/255", apart);
    RblUnloadPackedMaterial(&plain);
    UnloadImage(straight);
    RblUnloadPackedMaterial(&packed);
    // with alpha coverage kept, the scaled levels stay premultiplied (colour scaled with its alpha:
    // no texel brighter than its alpha)
    src.albedo = albedo; src.premultipliedAlpha = true; src.alphaCoverage = 0.5f;
    RT_CHECK(RblPackMaterial(&src, &packed), "coverage pack");
    int over = 0;
    for (int i = 0; (packed.albedo.data != NULL) && (i < 16 + 4 + 1); i++)
    {
        const unsigned char *q = (const unsigned char *)packed.albedo.data + i*4;
        over += (q[0] > q[3]) || (q[1] > q[3]) || (q[2] > q[3]);
    }
    RT_CHECK(over == 0, "%d texels hold more colour than alpha after the coverage scaling", over);
    RblUnloadPackedMaterial(&packed);
    UnloadImage(albedo);
}

// ---- the real exporter files (../shared/atlases) ---------------------------------------------------

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
        RT_CHECK(RblIsAtlasValid(a) && a.frameCount == frames[i], "%s: valid %d, %d frames (expected %d)", files[i], RblIsAtlasValid(a), a.frameCount, frames[i]);
        if (!RblIsAtlasValid(a)) continue;
        bool libgdx = (a.format == RBL_ATLAS_LIBGDX);
        for (int p = 0; p < a.pageCount; p++)
        {
            // the sheet the loader found (test-trim-rotation.json names test.png: found by the json's own name)
            Image sheet = LoadImage(a.pages[p].image);
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
    if (RblIsAtlasValid(small) && RblIsAtlasValid(big) && smallSheet.data && bigSheet.data)
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
    for (int t = 0; RblIsAtlasValid(ase) && t < ase.tagCount; t++)
        for (int f = ase.tags[t].from; f <= ase.tags[t].to; f++)
        {
            char want[96]; snprintf(want, sizeof(want), "%s:%d", ase.tags[t].name, f - ase.tags[t].from);
            if (strcmp(ase.frames[f].name, want) != 0) tagBad++;
        }
    RT_CHECK(RblIsAtlasValid(ase) && ase.tagCount == 11 && tagBad == 0, "frames.json: %d tag frames misplaced", tagBad);
    RblUnloadAtlas(&ase);
    ase = RblLoadAtlas(SHARED_ATLASES "aseprite/player.json");
    tagBad = 0;
    for (int t = 0; RblIsAtlasValid(ase) && t < ase.tagCount; t++)
        for (int f = ase.tags[t].from; f <= ase.tags[t].to; f++)
        {
            char want[96]; snprintf(want, sizeof(want), "%s:%d", ase.tags[t].name, f);
            if (strcmp(ase.frames[f].name, want) != 0) tagBad++;
        }
    int climb = RblAtlasFindTag(&ase, "climb");
    RT_CHECK(RblIsAtlasValid(ase) && ase.tagCount == 18 && tagBad == 0 && climb >= 0 && ase.tags[climb].repeat == 2 && ase.frames[0].duration == 0.25f, "player.json: %d misplaced, climb repeat", tagBad);
    RblUnloadAtlas(&ase);

    // Format meaning, libGDX: the turned frames of libgdx-packed (one animation on 120x175 canvases)
    // rebuilt counter-clockwise match the upright frame 0000 better than half-turned
    RblAtlas gdx = RblLoadAtlas(SHARED_ATLASES "libgdx/libgdx-packed.atlas");
    Image gs = LoadImage(SHARED_ATLASES "libgdx/libgdx-packed.png");
    if (RblIsAtlasValid(gdx) && gs.data)
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

// A sprite update's checks (branch-free one at a time, and lanes over a run) accept exactly what
// rbl__spriteProblem accepts, and the four-lane chunk bounds equal the one-at-a-time ones bit for
// bit: 400,000 sprites with each field on its bound's edges (position and start at 2^120, NaN, Inf;
// scale -0, 0, 1e15 and the next float, negative, NaN; half-float speeds Inf, NaN, the largest
// finite, negative zero; mode bits 4..7; frames and tags at and past the atlas's counts, tag
// 0xFFFF), runs of them under three atlas sizes, and 300 chunks of valid sprites with hidden ones
// (scale 0 and -0), repeated coordinates, chunks whose least or greatest coordinate is a tie of +0
// and -0 (bounds keep +0), chunks partly filled, all hidden, and written in two parts
static void test_sprite_update_checks_and_chunk_bounds_equal_the_one_at_a_time_ones(void)
{
    rbl__SpriteBufferState b;
    memset(&b, 0, sizeof(b));
    b.frameCount = 7; b.tagCount = 3;
    const float edgeF[] = { 0.0f, -0.0f, 1.0f, -3.5f, 1.3292279e36f, -1.3292279e36f, 1.329228e36f, -1.329228e36f, NAN, INFINITY, -INFINITY, 1e-40f };
    const float scaleF[] = { 0.0f, -0.0f, 1.0f, 1e15f, nextafterf(1e15f, INFINITY), -1e-30f, NAN, INFINITY, 3e-39f, 0.01f };
    const unsigned short speedH[] = { 0x0000, 0x3C00, 0x7BFF, 0x7C00, 0x7E00, 0x8000, 0xFC00, 0x03FF, 0x7C01 };
    const unsigned short modeH[] = { 0x00, RBL_SPRITE_ANIMATED, RBL_SPRITE_ANIMATED | 0x0300, 0x10, 0x80, RBL_SPRITE_FLIP_X, 0xFF00, 0x40 | RBL_SPRITE_ANIMATED };
    const unsigned short frameH[] = { 0, 2, 3, 6, 7, 0xFFFF, 0xFFFE, 100 };
    unsigned int seed = 99u;
    int disagree = 0, accepted = 0;
    enum { EDGES = 400000 };
    RblSpriteInstance *all = (RblSpriteInstance *)calloc(EDGES, sizeof(RblSpriteInstance));
    bool *good = (bool *)calloc(EDGES, sizeof(bool));
    if ((all == NULL) || (good == NULL)) { RT_CHECK(false, "out of memory"); free(all); free(good); return; }
    for (int i = 0; i < EDGES; i++)
    {
        RblSpriteInstance p;
        memset(&p, 0, sizeof(p));
        // each field on an edge one time in three, else an ordinary value
        #define SPR_EDGE(ordinary, edges, n) ((rtRandom(&seed)%3u == 0u)? (edges)[rtRandom(&seed)%(n)] : (ordinary))
        p.position = (Vector3){ SPR_EDGE(1.0f, edgeF, 12u), SPR_EDGE(-2.0f, edgeF, 12u), SPR_EDGE(0.5f, edgeF, 12u) };
        p.scale = SPR_EDGE(0.25f, scaleF, 10u);
        p.start = SPR_EDGE(3.0f, edgeF, 12u);
        p.speed = SPR_EDGE((unsigned short)0x3C00, speedH, 9u);
        p.mode = SPR_EDGE((unsigned short)0, modeH, 8u);
        p.frame = SPR_EDGE((unsigned short)1, frameH, 8u);
        #undef SPR_EDGE
        p.rotation = (unsigned short)rtRandom(&seed);
        bool fast = rbl__spriteOk(&b, &p), lanes = rbl__spritesOk(&b, &p, 1), slow = (rbl__spriteProblem(&b, &p) == NULL);
        disagree += (fast != slow) + (lanes != slow);
        accepted += slow;
        all[i] = p; good[i] = slow;
    }
    printf("    checks: %d of %d disagree (%d accepted)\n", disagree, EDGES, accepted);
    RT_CHECK((disagree == 0) && (accepted > 40000) && (accepted < 360000), "%d disagree, %d accepted", disagree, accepted);
    // Runs of 0..64 of them at once, accepted ones with (half the time) one rejected one put in:
    // accepted exactly when every one is; the same under other atlas sizes (no frames at all, one
    // tag; frame and tag counts past 16 bits)
    int runsDiffer = 0, runsAccepted = 0, runs = 0;
    const int sizes[3][2] = { { 7, 3 }, { 0, 1 }, { 70000, 65536 } };
    int *pool[2] = { (int *)malloc(EDGES*sizeof(int)), (int *)malloc(EDGES*sizeof(int)) };
    RblSpriteInstance run[64], runCopy[64];
    float runPivots[64*4], runBounds[7];
    rbl__SpriteBufferState held = b;
    for (int k = 0; (k < 3) && (pool[0] != NULL) && (pool[1] != NULL); k++)
    {
        b.frameCount = sizes[k][0]; b.tagCount = sizes[k][1];
        held.frameCount = b.frameCount; held.tagCount = b.tagCount;
        const rbl__SpriteChecks checks = rbl__spriteChecks(&held);
        int counts[2] = { 0, 0 };
        for (int i = 0; i < EDGES; i++) { int g = (rbl__spriteProblem(&b, &all[i]) == NULL); pool[g][counts[g]++] = i; }
        for (int r = 0; (r < 20000) && (counts[0] > 0) && (counts[1] > 0); r++, runs++)
        {
            int n = (int)(rtRandom(&seed)%65u);
            for (int i = 0; i < n; i++) run[i] = all[pool[1][rtRandom(&seed)%(unsigned int)counts[1]]];
            if ((n > 0) && (rtRandom(&seed)%2u)) run[rtRandom(&seed)%(unsigned int)n] = all[pool[0][rtRandom(&seed)%(unsigned int)counts[0]]];
            bool every = true;
            for (int i = 0; i < n; i++) every = every && (rbl__spriteProblem(&b, &run[i]) == NULL);
            runsDiffer += (rbl__spritesOk(&b, run, n) != every);
            // checked as a whole chunk is written (a whole-buffer update's one pass)
            if (n > 0) runsDiffer += (rbl__writeSpriteChunk(&held, runPivots, runBounds, n, 0, 0, n, run, runCopy, &checks) != every) + (memcmp(runCopy, run, (size_t)n*sizeof(RblSpriteInstance)) != 0);
            runsAccepted += every;
        }
    }
    free(pool[0]); free(pool[1]);
    b.frameCount = 7; b.tagCount = 3;
    printf("    runs: %d of %d differ (%d accepted)\n", runsDiffer, runs, runsAccepted);
    RT_CHECK((runsDiffer == 0) && (runsAccepted > runs/20) && (runsAccepted < runs - runs/20), "%d of %d runs differ, %d accepted", runsDiffer, runs, runsAccepted);
    free(all); free(good);

    // Chunk bounds: four lanes (two sets, either zero's sign) equal one sprite at a time, from the
    // pivot copy and from a chunk's write (whole: from the write's own lanes; a part: from the copy)
    enum { CHUNKS = 300 };
    b.capacity = b.count = CHUNKS*RBL__SPRITE_CHUNK - 37;
    RblSpriteInstance *in = (RblSpriteInstance *)calloc((size_t)b.capacity, sizeof(RblSpriteInstance)), *gpu = (RblSpriteInstance *)calloc((size_t)b.capacity, sizeof(RblSpriteInstance));
    float *pivots = (float *)calloc((size_t)b.capacity*4, sizeof(float));
    float *lanes = (float *)calloc((size_t)CHUNKS*7, sizeof(float)), *one = (float *)calloc((size_t)CHUNKS*7, sizeof(float)), *written = (float *)calloc((size_t)CHUNKS*7, sizeof(float));
    if ((in == NULL) || (gpu == NULL) || (pivots == NULL) || (lanes == NULL) || (one == NULL) || (written == NULL))
    {
        RT_CHECK(false, "out of memory"); free(in); free(gpu); free(pivots); free(lanes); free(one); free(written); return;
    }
    const float coordF[] = { 0.0f, -0.0f, 1.5f, -1.5f, 2.0f, -7.25f, 1e30f, -1e30f };
    for (int i = 0; i < b.count; i++)
    {
        RblSpriteInstance *p = &in[i];
        int c = i/RBL__SPRITE_CHUNK;
        for (int k = 0; k < 3; k++) ((float *)&p->position)[k] = (rtRandom(&seed)%3u)? rtRandomRange(&seed, -50.0f, 50.0f) : coordF[rtRandom(&seed)%8u];
        // chunks whose least (or greatest) coordinate is a tie of +0 and -0
        for (int k = 0; ((c % 5) == 1) && (k < 3); k++) ((float *)&p->position)[k] = coordF[rtRandom(&seed)%3u];
        for (int k = 0; ((c % 5) == 2) && (k < 3); k++) ((float *)&p->position)[k] = -coordF[rtRandom(&seed)%3u];
        unsigned int h = rtRandom(&seed)%5u;
        p->scale = ((c % 7) == 3)? 0.0f : (h == 0)? 0.0f : (h == 1)? -0.0f : rtRandomRange(&seed, 0.001f, 4.0f);
        p->start = (float)i; p->rotation = (unsigned short)i; p->frame = (unsigned short)(i%7); p->tint = (Color){ (unsigned char)i, 1, 2, 3 };
    }
    // Written chunk by chunk: whole ones, and every 3rd in two parts (the second part's bounds then
    // come from the copy, holding the first part)
    b.pivots = pivots; b.bounds = written;
    for (int c = 0; c < CHUNKS; c++)
    {
        int from = c*RBL__SPRITE_CHUNK, to = (c + 1)*RBL__SPRITE_CHUNK;
        if (to > b.count) to = b.count;
        int cut = ((c % 3) == 0)? from + 1 + (int)(rtRandom(&seed)%(unsigned int)(to - from - 1)) : from;
        if (cut > from) rbl__writeSpriteChunk(&b, b.pivots, b.bounds, b.count, c, from, cut, in + from, gpu + from, NULL);
        rbl__writeSpriteChunk(&b, b.pivots, b.bounds, b.count, c, cut, to, in + cut, gpu + cut, NULL);
    }
    int copyDiffer = 0;
    for (int i = 0; i < b.count; i++)
    {
        const float want[4] = { in[i].position.x, in[i].position.y, in[i].position.z, in[i].scale };
        copyDiffer += (memcmp(pivots + 4*i, want, sizeof(want)) != 0) + (memcmp(&gpu[i], &in[i], sizeof(RblSpriteInstance)) != 0);
    }
    int differ = 0, empty = 0, negativeZero = 0;
    for (int c = 0; c < CHUNKS; c++)
    {
        rbl__spriteChunkBounds(b.pivots, lanes, b.count, c);
        rbl__spriteChunkBoundsScalar(b.pivots, one, b.count, c);
        bool seen = one[7*c + 6] >= 0.0f;
        differ += (memcmp(lanes + 7*c, one + 7*c, (seen? 7 : 1)*sizeof(float)) != 0) + (memcmp(written + 7*c, one + 7*c, (seen? 7 : 1)*sizeof(float)) != 0);
        for (int k = 0; seen && (k < 6); k++) negativeZero += (one[7*c + k] == 0.0f) && signbit(one[7*c + k]);
        empty += !seen;
    }
    printf("    chunk bounds: %d of %d differ (%d with nothing visible), %d -0 bounds; %d copies differ\n", differ, 2*CHUNKS, empty, negativeZero, copyDiffer);
    RT_CHECK((differ == 0) && (empty > 30) && (negativeZero == 0) && (copyDiffer == 0), "%d chunks' bounds differ, %d empty, %d -0, %d copies differ", differ, empty, negativeZero, copyDiffer);
    free(in); free(gpu); free(pivots); free(lanes); free(one); free(written);
}

