// Atlas frames on the GPU: every frame of an atlas drawn through the batch and, where GLSL 3 runs,
// through one instanced draw with a frame per instance, at 1 texel per pixel (orthographic camera),
// lit by a white ambient (albedo back within rounding). Expected: the frame's untrimmed canvas
// rebuilt on the CPU by the format's meaning (ImageFromImage + ImageRotateCW/CCW, pasted at its trim
// offset), its pivot pixel where the billboard's position projects. Hand-written fixtures (noise
// sheets made here) always; the real exporter sheets of ../shared/atlases when present.
// Included by test_gpu_main.c.

#define ATLAS_RT_W 1024
#define ATLAS_RT_H 256

// Deterministic opaque noise sheet
static Image noiseSheet(int w, int h, unsigned int seed)
{
    Image img = GenImageColor(w, h, BLACK);
    Color *px = (Color *)img.data;
    for (int i = 0; i < w*h; i++)
    {
        unsigned int r = rtRandom(&seed);
        px[i] = (Color){ (unsigned char)(r & 255), (unsigned char)((r >> 8) & 255), (unsigned char)((r >> 16) & 255), 255 };
    }
    return img;
}

static Image atlasCanvas(Image sheet, const RblAtlasFrame *f, bool libgdx)
{
    Image up = ImageFromImage(sheet, f->block);
    if (f->flags & RBL_FRAME_ROTATED) { if (libgdx) ImageRotateCW(&up); else ImageRotateCCW(&up); }
    Image canvas = GenImageColor((int)f->size.x, (int)f->size.y, BLANK);
    ImageDraw(&canvas, up, (Rectangle){ 0, 0, (float)up.width, (float)up.height }, f->trim, WHITE);
    UnloadImage(up);
    return canvas;
}

// Draws every frame that fits (left to right) and compares each region with its canvas; returns
// the number of differing pixels (opaque texels: any channel off by more than 2; transparent: not black)
static int drawAtlasAndCompare(const RblAtlas *a, int page, Image sheet, bool instanced, int *framesDrawn)
{
    ImageFormat(&sheet, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Texture2D tex = LoadTextureFromImage(sheet);
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.instanced = instanced;
    Shader lit = RblLoadLitShader(desc);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = tex;
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    Camera3D cam; memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0, 0, 10 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = (float)ATLAS_RT_H; cam.projection = CAMERA_ORTHOGRAPHIC;
    // layout: canvases left to right, top edge at row 4; pivot pixel -> world position
    int x0[256], y0 = 4, cursor = 4, n = 0, index[256];
    RblInstance inst[256];
    RblBillboard bb[256];
    for (int f = 0; (f < a->frameCount) && (n < 256); f++)
    {
        const RblAtlasFrame *fr = &a->frames[f];
        if (fr->page != page) continue;
        if ((cursor + (int)fr->size.x + 4 > ATLAS_RT_W) || ((int)fr->size.y + 8 > ATLAS_RT_H)) continue;
        double px = cursor + (double)fr->pivot.x*fr->size.x, py = y0 + (double)fr->pivot.y*fr->size.y;     // screen pixels
        Vector3 pos = { (float)(px - ATLAS_RT_W/2.0), (float)(ATLAS_RT_H/2.0 - py), 0.0f };
        memset(&bb[n], 0, sizeof(bb[n])); memset(&inst[n], 0, sizeof(inst[n]));
        RT_CHECK(RblAtlasBillboard(a, f, 1.0f, &bb[n]) && RblAtlasInstance(a, f, 1.0f, &inst[n]), "frame %d refused", f);
        bb[n].position = pos; inst[n].position = pos;
        x0[n] = cursor; index[n] = f;
        cursor += (int)fr->size.x + 4;
        n++;
    }
    RenderTexture2D rt = LoadRenderTexture(ATLAS_RT_W, ATLAS_RT_H);
    RblBatch batch = RblLoadBatch(n);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(n);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    if (instanced) RT_CHECK(RblDrawInstanced(&buf, cam, m, (RblInstancedDesc){ 0 }, inst, n) == n, "instanced draw");
    else { RblBeginBatch(&batch, cam); for (int i = 0; i < n; i++) RblBatchAdd(&batch, m, &bb[i]); RblEndBatch(&batch); }
    EndMode3D(); EndTextureMode();
    Image out = rtReadTarget(rt);
    int bad = 0;
    for (int i = 0; i < n; i++)
    {
        const RblAtlasFrame *fr = &a->frames[index[i]];
        Image canvas = atlasCanvas(sheet, fr, a->format == RBL_ATLAS_LIBGDX);
        int frameBad = 0;
        for (int y = 0; y < canvas.height; y++)
            for (int x = 0; x < canvas.width; x++)
            {
                Color want = GetImageColor(canvas, x, y), got = rtPixel(out, x0[i] + x, y0 + y);
                if (want.a == 255) frameBad += (abs(want.r - got.r) > 2) || (abs(want.g - got.g) > 2) || (abs(want.b - got.b) > 2);
                else if (want.a == 0) frameBad += (got.r > 2) || (got.g > 2) || (got.b > 2);
            }
        if (frameBad > 0) printf("    %s frame %s: %d px differ\n", instanced? "instanced" : "batched", fr->name, frameBad);
        bad += frameBad;
        UnloadImage(canvas);
    }
    if (bad > 0) rtSaveImage(out, instanced? "instanced" : "batched");
    *framesDrawn = n;
    UnloadImage(out);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch); RblUnloadInstanceBuffer(&buf);
    RblUnloadLitShader(&lit);
    UnloadTexture(tex);
    MemFree(m.maps);
    return bad;
}

static void test_atlas_frames_drawn_batched_and_instanced_equal_their_rebuilt_canvases(void)
{
    int total = 0, frames = 0, n;
    for (int pass = 0; pass < 2; pass++)
    {
        bool instanced = (pass == 1);
        if (instanced && !rtGlsl3()) break;
        // hand-written fixtures over noise sheets: trimmed, pivoted, rotated clockwise (TexturePacker),
        // rotated counter-clockwise with bottom offsets (libGDX)
        RblAtlas tp = RblLoadAtlas("tests/fuzz/corpus/texturepacker/hash.json"), gdx = RblLoadAtlas("tests/fuzz/corpus/libgdx/old.atlas");
        Image s1 = noiseSheet(128, 64, 7u), s2 = noiseSheet(64, 64, 9u);
        total += drawAtlasAndCompare(&tp, 0, s1, instanced, &n); frames += n;
        total += drawAtlasAndCompare(&gdx, 0, s2, instanced, &n); frames += n;
        UnloadImage(s1); UnloadImage(s2);
        RblUnloadAtlas(&tp); RblUnloadAtlas(&gdx);
        // the real sheets
        static const char *files[3] = { "texturepacker/building1.json", "texturepacker/test-trim-rotation.json", "libgdx/libgdx-packed.atlas" };
        static const char *sheets[3] = { "texturepacker/building1.png", "texturepacker/test-trim-rotation.png", "libgdx/libgdx-packed.png" };
        for (int i = 0; (i < 3) && DirectoryExists("../shared/atlases/"); i++)
        {
            char path[256];
            snprintf(path, sizeof(path), "../shared/atlases/%s", files[i]);
            RblAtlas a = RblLoadAtlas(path);
            snprintf(path, sizeof(path), "../shared/atlases/%s", sheets[i]);
            Image sheet = LoadImage(path);
            RT_CHECK(RblIsAtlasValid(&a) && sheet.data != NULL, "%s", files[i]);
            if (RblIsAtlasValid(&a) && sheet.data != NULL) { total += drawAtlasAndCompare(&a, 0, sheet, instanced, &n); frames += n; }
            UnloadImage(sheet);
            RblUnloadAtlas(&a);
        }
    }
    printf("    %d frame draws compared\n", frames);
    RT_CHECK(frames >= 6 && total == 0, "%d pixels differ over %d frame draws", total, frames);
}

// A rotated frame lights as its upright twin: the same normal tile (tilted toward the sprite's
// right) stored upright, turned clockwise (TexturePacker) and counter-clockwise (libGDX), with the
// vectors in the stored texture's axes (tangent space = the sheet's u, v); lit from the right,
// the three draws agree
static void test_atlas_rotated_frames_light_like_the_upright_frame(void)
{
    static const char json[] =
        "{\"frames\": {\"up\": {\"frame\": {\"x\":0,\"y\":0,\"w\":16,\"h\":8}}, \"cw\": {\"frame\": {\"x\":16,\"y\":0,\"w\":16,\"h\":8}, \"rotated\": true}}, \"meta\": {\"size\": {\"w\":32,\"h\":16}}}";
    static const char gdxText[] = "s.png\nsize: 32, 16\nccw\n  rotate: true\n  xy: 24, 0\n  size: 16, 8\n";
    RblAtlas tp = RblLoadAtlasFromMemory(json, (int)strlen(json), RBL_ATLAS_AUTO), gdx = RblLoadAtlasFromMemory(gdxText, (int)strlen(gdxText), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(&tp) && RblIsAtlasValid(&gdx), "fixtures");
    // normal sheet: upright tile at x 0..15 rows 0..7 with n = (0.6, 0, 0.8) (toward the sprite's right);
    // clockwise block at 16..23 x 0..15: the right turns to the image's down, n = (0, -0.6, 0.8);
    // counter-clockwise block at 24..31: the right turns to up, n = (0, 0.6, 0.8)
    Image normal = GenImageColor(32, 16, normalTexel(0, 0, 1));
    ImageDrawRectangle(&normal, 0, 0, 16, 8, normalTexel(0.6f, 0.0f, 0.8f));
    ImageDrawRectangle(&normal, 16, 0, 8, 16, normalTexel(0.0f, -0.6f, 0.8f));
    ImageDrawRectangle(&normal, 24, 0, 8, 16, normalTexel(0.0f, 0.6f, 0.8f));
    Image whiteImage = GenImageColor(32, 16, WHITE);     // the sheet's size: the frames' UVs hold for both maps
    Texture2D ntex = LoadTextureFromImage(normal), white = LoadTextureFromImage(whiteImage);
    UnloadImage(whiteImage);
    UnloadImage(normal);
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.material.normalEncoding = RBL_NORMAL_RGB;
    Shader lit = RblLoadLitShader(desc);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    m.maps[MATERIAL_MAP_NORMAL].texture = ntex;
    Camera3D cam = frontCamera();
    int lum[3][2];
    for (int side = 0; side < 2; side++)
    {
        RblLight l = pointLight((Vector3){ side? -3.0f : 3.0f, 0.0f, 1.0f }, 6.0f);
        RT_CHECK(renderSetLights(&l, 1, BLACK), "scene");
        for (int k = 0; k < 3; k++)
        {
            RblBillboard b; memset(&b, 0, sizeof(b));
            const RblAtlas *a = (k == 2)? &gdx : &tp;
            RT_CHECK(RblAtlasBillboard(a, (k == 2)? 0 : k, 0.125f, &b), "billboard");
            RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
            BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
            RblDrawBillboard(cam, m, b);
            EndMode3D(); EndTextureMode();
            Image img = rtReadTarget(rt);
            UnloadRenderTexture(rt);
            lum[k][side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
            UnloadImage(img);
        }
    }
    printf("    lit from +x / -x: upright %d / %d, clockwise %d / %d, counter-clockwise %d / %d\n", lum[0][0], lum[0][1], lum[1][0], lum[1][1], lum[2][0], lum[2][1]);
    RT_CHECK(lum[0][0] > lum[0][1] + 30, "upright frame: the right side is not the lit one");
    for (int k = 1; k < 3; k++)
        RT_CHECK(abs(lum[k][0] - lum[0][0]) <= 3 && abs(lum[k][1] - lum[0][1]) <= 3, "%s frame lights %d / %d, upright %d / %d", (k == 1)? "clockwise" : "counter-clockwise", lum[k][0], lum[k][1], lum[0][0], lum[0][1]);
    RblUnloadLitShader(&lit);
    UnloadTexture(ntex); UnloadTexture(white);
    MemFree(m.maps);
    RblUnloadAtlas(&tp); RblUnloadAtlas(&gdx);
}
