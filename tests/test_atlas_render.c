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
        // world units per pixel = the page's scale: one texel per pixel (building1 is exported at 0.5)
        float unit = a->pages[page].scale;
        RT_CHECK(RblAtlasBillboard(a, f, unit, &bb[n]) && RblAtlasInstance(a, f, unit, &inst[n]), "frame %d refused", f);
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
        RT_CHECK(rtAtlasFixtures() != NULL, "fixtures");
        RblAtlas tp = RblLoadAtlas("build/tests/atlas/texturepacker/hash.json"), gdx = RblLoadAtlas("build/tests/atlas/libgdx/old.atlas");
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
            RT_CHECK(RblIsAtlasValid(a) && sheet.data != NULL, "%s", files[i]);
            if (RblIsAtlasValid(a) && sheet.data != NULL) { total += drawAtlasAndCompare(&a, 0, sheet, instanced, &n); frames += n; }
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
    RT_CHECK(RblIsAtlasValid(tp) && RblIsAtlasValid(gdx), "fixtures");
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
        RblLight l = rtPointLight((Vector3){ side? -3.0f : 3.0f, 0.0f, 1.0f }, 6.0f);
        RT_CHECK(renderSetLights(&l, 1, BLACK), "scene");
        for (int k = 0; k < 3; k++)
        {
            RblBillboard b; memset(&b, 0, sizeof(b));
            const RblAtlas *a = (k == 2)? &gdx : &tp;
            RT_CHECK(RblAtlasBillboard(a, (k == 2)? 0 : k, 0.125f, &b), "billboard");
            b.position.y = -0.5f*b.size.y;      // the card's centre on the target's (it stands on its bottom centre)
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

// ---- a page's textures in one call, its normal sheet, premultiplied pages (issue #28) ------------
// One texel per pixel: an orthographic camera over a w x h target, a card of w' x h' world units at
// (x, y) pixels from the top-left (its pivot at its bottom-left corner)
static Camera3D pixelCamera(int height)
{
    Camera3D cam; memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0, 0, 10 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = (float)height; cam.projection = CAMERA_ORTHOGRAPHIC;
    return cam;
}
static void pixelCard(RblBillboard *b, int w, int h, int x, int y, int rtW, int rtH)
{
    b->size = (Vector2){ (float)w, (float)h };
    b->origin = (Vector2){ 0, 0 };
    b->position = (Vector3){ (float)x - rtW/2.0f, rtH/2.0f - (float)(y + h), 0.0f };
}

// A normal tile n (unit, tangent space) as RGB8, and the vector the shader decodes from it
static Color normalRgb(double x, double y, double z) { return (Color){ (unsigned char)lround((x*0.5 + 0.5)*255.0), (unsigned char)lround((y*0.5 + 0.5)*255.0), (unsigned char)lround((z*0.5 + 0.5)*255.0), 255 }; }
static D3 normalDecoded(Color c) { return dNorm(d3(c.r/255.0*2.0 - 1.0, c.g/255.0*2.0 - 1.0, c.b/255.0*2.0 - 1.0)); }

static void test_atlas_page_and_its_normal_sheet_load_in_one_call_and_light_as_the_reference(void)
{
    // A 16x8 sheet of two white 8x8 frames; the normal sheet tilts the left one toward the sprite's
    // right (+x) and the right one toward its left, as an artist's normal pass would
    MakeDirectory("build/tests/atlas_gpu");
    Image sheet = GenImageColor(16, 8, WHITE), normals = GenImageColor(16, 8, BLANK);
    const Color tilt[2] = { normalRgb(0.6, 0.0, 0.8), normalRgb(-0.6, 0.0, 0.8) };
    ImageDrawRectangle(&normals, 0, 0, 8, 8, tilt[0]);
    ImageDrawRectangle(&normals, 8, 0, 8, 8, tilt[1]);
    ExportImage(sheet, "build/tests/atlas_gpu/hero.png");
    ExportImage(normals, "build/tests/atlas_gpu/hero_n.png");          // the "_n" convention
    ExportImage(normals, "build/tests/atlas_gpu/hero_nrm.png");        // a caller's own suffix
    ExportImage(normals, "build/tests/atlas_gpu/hero_bump.png");       // named by a Phaser 3 file
    UnloadImage(sheet); UnloadImage(normals);
    SaveFileText("build/tests/atlas_gpu/hero.json", (char *)"{\"frames\": {\"l\": {\"frame\": {\"x\":0,\"y\":0,\"w\":8,\"h\":8}}, \"r\": {\"frame\": {\"x\":8,\"y\":0,\"w\":8,\"h\":8}}},"
                 " \"meta\": {\"image\": \"hero.png\", \"size\": {\"w\":16,\"h\":8}}}");
    SaveFileText("build/tests/atlas_gpu/hero3.json", (char *)"{\"textures\": [{\"image\": \"hero.png\", \"normalMap\": \"hero_bump.png\", \"size\": {\"w\":16,\"h\":8},"
                 " \"frames\": [{\"filename\": \"l\", \"frame\": {\"x\":0,\"y\":0,\"w\":8,\"h\":8}}, {\"filename\": \"r\", \"frame\": {\"x\":8,\"y\":0,\"w\":8,\"h\":8}}]}]}");
    // The light comes from the right and toward the viewer: the left frame faces it more
    RblLight light; memset(&light, 0, sizeof(light));
    light.type = RBL_LIGHT_DIRECTIONAL; light.direction = (Vector3){ -1.0f, 0.0f, -1.0f }; light.color = (Color){ 255, 230, 200, 255 }; light.intensity = 1.5f;
    const Color ambient = { 40, 40, 50, 255 };
    RT_CHECK(renderSetLights(&light, 1, ambient), "scene");
    RefParams params; memset(&params, 0, sizeof(params));
    RefEnvironment env; memset(&env, 0, sizeof(env));
    env.ambient = ambient;
    Camera3D cam = pixelCamera(16);
    const char *files[3] = { "build/tests/atlas_gpu/hero.json", "build/tests/atlas_gpu/hero.json", "build/tests/atlas_gpu/hero3.json" };
    const char *suffix[3] = { NULL, "_nrm", NULL };
    int worst = 0, litDiff = 0;
    for (int k = 0; k < 3; k++)
    {
        RblAtlas a = RblLoadAtlas(files[k]);
        Material m = LoadMaterialDefault();
        RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
        desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
        bool ok = RblIsAtlasValid(a) && RblLoadAtlasTextures(&a, 0, suffix[k], &m, &desc.material);
        RT_CHECK(ok && desc.material.normalEncoding == RBL_NORMAL_RGB && !desc.material.premultipliedAlpha && m.maps[MATERIAL_MAP_NORMAL].texture.width == 16,
                 "%s (suffix %s): loaded %d, normal encoding %d", files[k], suffix[k]? suffix[k] : "NULL", ok, desc.material.normalEncoding);
        if (!ok) { RblUnloadAtlas(&a); UnloadMaterial(m); continue; }
        m.shader = RblLoadLitShader(desc);
        RenderTexture2D rt = LoadRenderTexture(32, 16);
        BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
        for (int f = 0; f < 2; f++)
        {
            RblBillboard b; memset(&b, 0, sizeof(b));
            RT_CHECK(RblAtlasBillboard(&a, f, 1.0f, &b), "frame %d", f);
            b.position = (Vector3){ -12.0f + 16.0f*f, -4.0f, 0.0f };     // feet at the bottom centre of pixels 0..15 / 16..31
            RblDrawBillboard(cam, m, b);
        }
        EndMode3D(); EndTextureMode();
        Image out = rtReadTarget(rt);
        // each frame's centre pixel against the double reference (Lambert, the decoded normal; the
        // card faces +Z with +U = +X and the map's +Y up)
        int lum[2];
        for (int f = 0; f < 2; f++)
        {
            RefSurface s; memset(&s, 0, sizeof(s));
            s.position = d3(0, 0, 0); s.normal = normalDecoded(tilt[f]); s.albedo = refRgb(1, 1, 1); s.occlusion = 1.0; s.specularMap = -1.0;
            RefRgb want = refFinishAt(&params, refShadeView(&params, &light, 1, &env, &s, d3(0, 0, 1)), 0.0);
            Color got = rtPixel(out, 4 + 16*f, 8);
            int d = abs(got.r - (int)lround(want.r*255.0));
            d = (abs(got.g - (int)lround(want.g*255.0)) > d)? abs(got.g - (int)lround(want.g*255.0)) : d;
            d = (abs(got.b - (int)lround(want.b*255.0)) > d)? abs(got.b - (int)lround(want.b*255.0)) : d;
            worst = (d > worst)? d : worst;
            lum[f] = got.r + got.g + got.b;
        }
        litDiff = lum[0] - lum[1];
        if (worst > 1) rtSaveImage(out, "normal-sheet");
        UnloadImage(out);
        UnloadRenderTexture(rt);
        RblUnloadLitShader(&m.shader);
        UnloadMaterial(m);      // frees the two textures RblLoadAtlasTextures put in the slots
        RblUnloadAtlas(&a);
    }
    printf("    sheet + normal sheet (\"_n\", \"_nrm\", Phaser 3 normalMap): worst %d/255 from the double reference, left - right %d\n", worst, litDiff);
    RT_CHECK(worst <= 1 && litDiff > 60, "lit frames %d/255 from the reference (left brighter by %d)", worst, litDiff);
}

// Premultiplied pages (libGDX pma): the lit program divides each filtered texel by its alpha and
// lights the straight colour; against a double reference of that (Lambert + ambient, sRGB decode,
// encode, alpha blending over the target), point-sampled at one texel per pixel and magnified 8x
// through bilinear filtering, where the alpha-weighted mean of neighbours meets transparent texels.
// The same texels through a program that takes them as straight colour are far off (the test can
// fail), and a straight sheet whose transparent texels are black darkens the filtered edges.
static void test_atlas_premultiplied_pages_light_and_blend_as_their_straight_colour(void)
{
    // straight colours and alphas (0..255 in steps), premultiplied as libGDX's packer stores them
    Image straight = GenImageColor(16, 8, BLANK), pma = GenImageColor(16, 8, BLANK);
    unsigned int seed = 1234u;
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++)
        {
            unsigned char a = (unsigned char)((x*17 + y*3)%256), r = (unsigned char)rtRandom(&seed), g = (unsigned char)rtRandom(&seed), b = (unsigned char)rtRandom(&seed);
            ((Color *)pma.data)[y*16 + x] = (Color){ (unsigned char)lround(r*a/255.0), (unsigned char)lround(g*a/255.0), (unsigned char)lround(b*a/255.0), a };
            ((Color *)straight.data)[y*16 + x] = (Color){ r, g, b, a };
        }
    // the page comes from a libGDX atlas that says pma: true, through RblLoadAtlasTextures
    MakeDirectory("build/tests/atlas_gpu");
    ExportImage(pma, "build/tests/atlas_gpu/pma.png");
    SaveFileText("build/tests/atlas_gpu/pma.atlas", (char *)"pma.png\nsize: 16, 8\nformat: RGBA8888\nfilter: Nearest, Nearest\nrepeat: none\npma: true\nall\n  rotate: false\n  xy: 0, 0\n  size: 16, 8\n");
    RblAtlas atlas = RblLoadAtlas("build/tests/atlas_gpu/pma.atlas");
    Material mPma = LoadMaterialDefault();
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
    RT_CHECK(RblIsAtlasValid(atlas) && atlas.pages[0].premultiplied && RblLoadAtlasTextures(&atlas, 0, "", &mPma, &desc.material) && desc.material.premultipliedAlpha, "pma page and layout");
    mPma.shader = RblLoadLitShader(desc);
    RblLitShaderDesc plainDesc = desc;
    plainDesc.material.premultipliedAlpha = false;
    Material mNaive = LoadMaterialDefault(), mStraight = LoadMaterialDefault();
    mNaive.shader = RblLoadLitShader(plainDesc);
    mNaive.maps[MATERIAL_MAP_ALBEDO].texture = mPma.maps[MATERIAL_MAP_ALBEDO].texture;
    mStraight.shader = RblLoadLitShader(plainDesc);
    RT_CHECK(RblIsLitShaderValid(mPma.shader) && RblIsLitShaderValid(mNaive.shader), "programs");
    Material *mats[3] = { &mPma, &mNaive, &mStraight };
    for (int k = 0; k < 3; k++) mats[k]->params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;     // every alpha blends
    RblLight light; memset(&light, 0, sizeof(light));
    light.type = RBL_LIGHT_DIRECTIONAL; light.direction = (Vector3){ -1.0f, -0.5f, -2.0f }; light.color = (Color){ 255, 210, 170, 255 }; light.intensity = 1.3f;
    const Color ambient = { 60, 50, 40, 255 }, bg = { 20, 70, 120, 255 };
    RT_CHECK(renderSetLights(&light, 1, ambient), "scene");
    RefParams params; memset(&params, 0, sizeof(params));
    RefEnvironment env; memset(&env, 0, sizeof(env));
    env.ambient = ambient;
    // lit output (0..1, encoded) of a straight sRGB texel colour
    #define PMA_SHADE(sr, sg, sb, outRgb) do { RefSurface s_; memset(&s_, 0, sizeof(s_)); s_.normal = d3(0, 0, 1); s_.occlusion = 1.0; s_.specularMap = -1.0; \
        s_.albedo = refRgb(srgbDecode(sr), srgbDecode(sg), srgbDecode(sb)); outRgb = refFinishAt(&params, refShadeView(&params, &light, 1, &env, &s_, d3(0, 0, 1)), 0.0); } while (0)
    // 1) one texel per pixel, point sampling: 128 texels of 16 alphas
    const int W = 32, H = 16;
    Camera3D cam = pixelCamera(H);
    int worst[2] = { 0, 0 }, worstTrue = 0;
    for (int k = 0; k < 2; k++)
    {
        RenderTexture2D rt = LoadRenderTexture(W, H);
        RblBillboard card; memset(&card, 0, sizeof(card));
        pixelCard(&card, 16, 8, 8, 4, W, H);
        BeginTextureMode(rt); ClearBackground(bg); BeginMode3D(cam);
        RblDrawBillboard(cam, *mats[k], card);
        EndMode3D(); EndTextureMode();
        Image out = rtReadTarget(rt);
        for (int y = 0; y < 8; y++)
            for (int x = 0; x < 16; x++)
            {
                Color p = ((Color *)pma.data)[y*16 + x], s = ((Color *)straight.data)[y*16 + x], got = rtPixel(out, 8 + x, 4 + y);
                double a = p.a/255.0;
                RefRgb lit, litTrue;
                PMA_SHADE((p.a > 0)? fmin(p.r/(double)p.a, 1.0) : 0.0, (p.a > 0)? fmin(p.g/(double)p.a, 1.0) : 0.0, (p.a > 0)? fmin(p.b/(double)p.a, 1.0) : 0.0, lit);
                PMA_SHADE(s.r/255.0, s.g/255.0, s.b/255.0, litTrue);
                const double w3[3] = { lit.r, lit.g, lit.b }, t3[3] = { litTrue.r, litTrue.g, litTrue.b }, b3[3] = { bg.r/255.0, bg.g/255.0, bg.b/255.0 };
                const int g3[3] = { got.r, got.g, got.b };
                for (int c = 0; c < 3; c++)
                {
                    int want = (int)lround((w3[c]*a + b3[c]*(1.0 - a))*255.0), wantTrue = (int)lround((t3[c]*a + b3[c]*(1.0 - a))*255.0);
                    if (abs(g3[c] - want) > worst[k]) worst[k] = abs(g3[c] - want);
                    if ((k == 0) && (abs(g3[c] - wantTrue) > worstTrue)) worstTrue = abs(g3[c] - wantTrue);
                }
            }
        if (((k == 0) && (worst[0] > 1)) || ((k == 1) && (worst[1] < 20))) rtSaveImage(out, (k == 0)? "pma" : "naive");
        UnloadImage(out);
        UnloadRenderTexture(rt);
    }
    printf("    point-sampled: premultiplied program %d/255 from the double reference (%d from the unquantised straight colour); the same texels taken as straight %d/255\n", worst[0], worstTrue, worst[1]);
    RT_CHECK(worst[0] <= 1 && worstTrue <= 2 && worst[1] >= 20, "premultiplied %d/255 (true colour %d), naive %d/255 (should be far)", worst[0], worstTrue, worst[1]);
    // 2) magnified 8x through bilinear filtering: opaque red | transparent | opaque green | half-transparent blue
    Image strip = GenImageColor(4, 1, BLANK), stripStraight = GenImageColor(4, 1, BLANK);
    const Color texels[4] = { { 200, 40, 30, 255 }, { 0, 0, 0, 0 }, { 40, 190, 60, 255 }, { 40, 60, 220, 128 } };
    for (int i = 0; i < 4; i++)
    {
        Color c = texels[i];
        ((Color *)strip.data)[i] = (Color){ (unsigned char)lround(c.r*c.a/255.0), (unsigned char)lround(c.g*c.a/255.0), (unsigned char)lround(c.b*c.a/255.0), c.a };
        ((Color *)stripStraight.data)[i] = c;       // transparent = black, as a straight exporter leaves it
    }
    Texture2D tPma = LoadTextureFromImage(strip), tStraight = LoadTextureFromImage(stripStraight);
    SetTextureFilter(tPma, TEXTURE_FILTER_BILINEAR); SetTextureFilter(tStraight, TEXTURE_FILTER_BILINEAR);
    SetTextureWrap(tPma, TEXTURE_WRAP_CLAMP); SetTextureWrap(tStraight, TEXTURE_WRAP_CLAMP);
    Texture2D keepPage = mPma.maps[MATERIAL_MAP_ALBEDO].texture;
    mPma.maps[MATERIAL_MAP_ALBEDO].texture = tPma;
    mStraight.maps[MATERIAL_MAP_ALBEDO].texture = tStraight;
    int worstLin[2] = { 0, 0 };
    for (int k = 0; k < 2; k++)
    {
        Material *m = (k == 0)? &mPma : &mStraight;
        RenderTexture2D rt = LoadRenderTexture(W, H);
        RblBillboard card; memset(&card, 0, sizeof(card));
        pixelCard(&card, 32, 8, 0, 4, W, H);
        BeginTextureMode(rt); ClearBackground(bg); BeginMode3D(cam);
        RblDrawBillboard(cam, *m, card);
        EndMode3D(); EndTextureMode();
        Image out = rtReadTarget(rt);
        for (int x = 0; x < 32; x++)
        {
            // texel-space sample point, clamped to the edge texels as the wrap mode does
            double u = (x + 0.5)/8.0 - 0.5;
            int i0 = (int)floor(u);
            double f = u - i0;
            int i1 = i0 + 1;
            i0 = (i0 < 0)? 0 : ((i0 > 3)? 3 : i0); i1 = (i1 < 0)? 0 : ((i1 > 3)? 3 : i1);
            Color c0 = ((Color *)strip.data)[i0], c1 = ((Color *)strip.data)[i1];
            double pr = ((1 - f)*c0.r + f*c1.r)/255.0, pg = ((1 - f)*c0.g + f*c1.g)/255.0, pb = ((1 - f)*c0.b + f*c1.b)/255.0, a = ((1 - f)*c0.a + f*c1.a)/255.0;
            RefRgb lit;
            PMA_SHADE((a > 0.0)? fmin(pr/a, 1.0) : 0.0, (a > 0.0)? fmin(pg/a, 1.0) : 0.0, (a > 0.0)? fmin(pb/a, 1.0) : 0.0, lit);
            const double w3[3] = { lit.r, lit.g, lit.b }, b3[3] = { bg.r/255.0, bg.g/255.0, bg.b/255.0 };
            for (int y = 4; y < 12; y++)
            {
                Color got = rtPixel(out, x, y);
                const int g3[3] = { got.r, got.g, got.b };
                for (int c = 0; c < 3; c++)
                {
                    int want = (int)lround((w3[c]*a + b3[c]*(1.0 - a))*255.0);
                    if (abs(g3[c] - want) > worstLin[k]) worstLin[k] = abs(g3[c] - want);
                }
            }
        }
        if (((k == 0) && (worstLin[0] > 2)) || ((k == 1) && (worstLin[1] < 10))) rtSaveImage(out, (k == 0)? "pma-bilinear" : "straight-bilinear");
        UnloadImage(out);
        UnloadRenderTexture(rt);
    }
    #undef PMA_SHADE
    printf("    bilinear 8x: premultiplied %d/255 from the reference; a straight sheet with black transparent texels %d/255 (dark fringes)\n", worstLin[0], worstLin[1]);
    RT_CHECK(worstLin[0] <= 2 && worstLin[1] >= 10, "bilinear: premultiplied %d/255 (limit 2), straight %d/255 (should show fringes)", worstLin[0], worstLin[1]);
    mPma.maps[MATERIAL_MAP_ALBEDO].texture = keepPage;
    UnloadTexture(tPma); UnloadTexture(tStraight); UnloadImage(strip); UnloadImage(stripStraight);
    RblUnloadLitShader(&mPma.shader); RblUnloadLitShader(&mNaive.shader); RblUnloadLitShader(&mStraight.shader);
    UnloadTexture(keepPage);
    MemFree(mPma.maps); MemFree(mNaive.maps); MemFree(mStraight.maps);
    RblUnloadAtlas(&atlas);
    UnloadImage(straight); UnloadImage(pma);
}


// (uses test_translucent.c's card helpers, included before this file)
// Packed maps of a non-power-of-two atlas: full mip chains where the context samples them (GL, ES 3),
// level 0 alone with clamped edges on ES 2 / WebGL1 (which read such a texture with mips as black);
// the card renders its colour either way
static void test_atlas_npot_packed_sheet_uploads_what_the_context_can_sample(void)
{
    Image albedo = GenImageColor(24, 20, (Color){ 200, 100, 50, 255 });
    RblMaterialSource src;
    memset(&src, 0, sizeof(src));
    src.albedo = albedo;
    src.mipmaps = true;
    RblPackedMaterial packed;
    RT_CHECK(RblPackMaterial(&src, &packed), "pack");
    Material m = sprMaterial(solidTexture(WHITE), 0.0f);
    UnloadTexture(m.maps[MATERIAL_MAP_ALBEDO].texture);
    RT_CHECK(RblLoadPackedTextures(&packed, &m), "upload");
    int want = (rlGetVersion() == RL_OPENGL_ES_20)? 1 : packed.albedo.mipmaps;
    RT_CHECK(m.maps[MATERIAL_MAP_ALBEDO].texture.mipmaps == want, "albedo uploaded with %d levels, expected %d", m.maps[MATERIAL_MAP_ALBEDO].texture.mipmaps, want);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene refused");
    RenderTexture2D rt = LoadRenderTexture(SPR_TARGET, SPR_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(sprCamera());
    RblBillboard b = sprCard(0.0f, 0.0f);
    b.size = (Vector2){ 0.3f, 0.3f }; b.origin = (Vector2){ 0.15f, 0.15f };     // minified: mips would be read
    RblDrawBillboard(sprCamera(), m, b);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    Color c = rtPixel(img, SPR_TARGET/2, SPR_TARGET/2);
    RT_CHECK((abs(c.r - 200) <= 2) && (abs(c.g - 100) <= 2) && (abs(c.b - 50) <= 2), "minified NPOT card (%d %d %d), expected (200 100 50)", c.r, c.g, c.b);
    printf("    24x20 packed atlas: %d levels uploaded, minified card (%d %d %d)\n", m.maps[MATERIAL_MAP_ALBEDO].texture.mipmaps, c.r, c.g, c.b);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    UnloadTexture(m.maps[MATERIAL_MAP_ALBEDO].texture);
    m.maps[MATERIAL_MAP_ALBEDO].texture.id = 0;
    sprUnloadMaterial(&m);
    RblUnloadPackedMaterial(&packed);
    UnloadImage(albedo);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_ATLAS_RENDER_TESTS \
    RT_TEST(test_atlas_npot_packed_sheet_uploads_what_the_context_can_sample), \
    RT_TEST(test_atlas_frames_drawn_batched_and_instanced_equal_their_rebuilt_canvases), \
    RT_TEST(test_atlas_rotated_frames_light_like_the_upright_frame), \
    RT_TEST(test_atlas_page_and_its_normal_sheet_load_in_one_call_and_light_as_the_reference), \
    RT_TEST(test_atlas_premultiplied_pages_light_and_blend_as_their_straight_colour)
