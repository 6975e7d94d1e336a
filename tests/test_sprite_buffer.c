// Resident sprite buffers (RblSpriteBuffer): 32-byte sprites uploaded once, animated on the GPU from
// a frame table, culled by chunk. References: the CPU player (RblPlaySprite / RblUpdateSprite /
// RblSpriteBlend) step by step, RblBillboardVertices for the quads, and RblDrawInstanced drawing the
// same sprites as RblInstances set by RblAtlasInstance. Needs tf_capture.h (test_instanced.c).
// Included by gpu_tests.h.

// Seven trimmed frames (one stored rotated), durations multiples of 1/8 s (exact in binary, so a
// 1/64 s sweep lands on every duration boundary exactly); tags in every direction, with repeats
static const char sbAtlasText[] =
    "{\"frames\": ["
    "{\"filename\": \"f0\", \"frame\": {\"x\":0,\"y\":0,\"w\":8,\"h\":12}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":2,\"y\":1,\"w\":8,\"h\":12}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 125},"
    "{\"filename\": \"f1\", \"frame\": {\"x\":8,\"y\":0,\"w\":10,\"h\":14}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":1,\"y\":2,\"w\":10,\"h\":14}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 250},"
    "{\"filename\": \"f2\", \"frame\": {\"x\":18,\"y\":0,\"w\":12,\"h\":16}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 375},"
    "{\"filename\": \"f3\", \"frame\": {\"x\":30,\"y\":0,\"w\":6,\"h\":14}, \"rotated\": true, \"trimmed\": true, \"spriteSourceSize\": {\"x\":0,\"y\":2,\"w\":6,\"h\":14}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 125},"
    "{\"filename\": \"f4\", \"frame\": {\"x\":0,\"y\":16,\"w\":12,\"h\":16}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 500},"
    "{\"filename\": \"f5\", \"frame\": {\"x\":12,\"y\":16,\"w\":6,\"h\":9}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":3,\"y\":7,\"w\":6,\"h\":9}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 250},"
    "{\"filename\": \"f6\", \"frame\": {\"x\":18,\"y\":16,\"w\":12,\"h\":16}, \"sourceSize\": {\"w\":12,\"h\":16}, \"duration\": 125}],"
    "\"meta\": {\"app\": \"aseprite\", \"size\": {\"w\":64,\"h\":64}, \"frameTags\": ["
    "{\"name\": \"fwd\", \"from\": 0, \"to\": 3, \"direction\": \"forward\"},"
    "{\"name\": \"rev\", \"from\": 1, \"to\": 4, \"direction\": \"reverse\"},"
    "{\"name\": \"pp\", \"from\": 2, \"to\": 5, \"direction\": \"pingpong\"},"
    "{\"name\": \"ppr\", \"from\": 0, \"to\": 3, \"direction\": \"pingpong_reverse\"},"
    "{\"name\": \"one\", \"from\": 6, \"to\": 6, \"direction\": \"pingpong\"},"
    "{\"name\": \"rep\", \"from\": 0, \"to\": 2, \"direction\": \"forward\", \"repeat\": \"3\"},"
    "{\"name\": \"pprep\", \"from\": 3, \"to\": 6, \"direction\": \"pingpong\", \"repeat\": \"5\"},"
    "{\"name\": \"ppr2\", \"from\": 1, \"to\": 5, \"direction\": \"pingpong_reverse\", \"repeat\": \"4\"}]}}";

static RblAtlas sbAtlas(void) { return RblLoadAtlasFromMemory(sbAtlasText, (int)strlen(sbAtlasText), RBL_ATLAS_AUTO); }

// The billboard a sprite stands for at a frame: RblAtlasBillboard's quad scaled, flipped about the
// pivot, rotation decoded (the CPU mirror of lit_instanced.vs.glsl's rblReadSprite)
static RblBillboard sbBillboard(const RblAtlas *atlas, const RblSpriteInstance *s, int frame)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = s->position;
    b.rotation = (float)s->rotation*(360.0f/65536.0f);
    RblAtlasBillboard(atlas, frame, s->scale, &b);
    if (s->mode & RBL_SPRITE_FLIP_X) { b.origin.x = b.size.x - b.origin.x; b.size.x = -b.size.x; }
    if (s->mode & RBL_SPRITE_FLIP_Y) { b.origin.y = b.size.y - b.origin.y; b.size.y = -b.size.y; }
    if (s->mode & RBL_SPRITE_ROUND_CYLINDER) b.flags |= RBL_ROUND_CYLINDER;
    b.tint = s->tint;
    return b;
}

static RblInstance sbInstance(const RblBillboard *b)
{
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.position = b->position; in.rotation = b->rotation; in.size = b->size; in.origin = b->origin;
    in.source = b->source; in.tint = b->tint; in.flags = b->flags;
    return in;
}

#define SB_TF_FLOATS 9      // fragPosition (3), fragTexCoord (2), fragTexCoord2 (2), fragFade (2)

// The instanced stage with cross-fade outputs, capturing the quad, both frames' coordinates and the weight
static GLu sbTfProgram(TfGl *gl)
{
    bool es = (rbl__glsl() == 300);
    char prologue[256];
    rbl__stagePrologue(es? 300 : 330, true, "#define RBL_LIGHTS 1\n#define RBL_CROSS_FADE\n#define RBL_SPRITE_BUFFER\n", prologue, sizeof(prologue));
    char *vs = rbl__joinStage(prologue, rbl__pass_lit_instanced_vs);
    GLu vsh = tfShader(gl, 0x8B31, vs);
    RBL_FREE(vs);
    GLu fsh = tfShader(gl, 0x8B30, es? "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(0.0); }\n"
                                     : "#version 330\nout vec4 c;\nvoid main() { c = vec4(0.0); }\n");
    GLu prog = gl->CreateProgram();
    gl->AttachShader(prog, vsh);
    gl->AttachShader(prog, fsh);
    const char *varyings[] = { "fragPosition", "fragTexCoord", "fragTexCoord2", "fragFade" };
    gl->TransformFeedbackVaryings(prog, 4, varyings, 0x8C8C);
    gl->LinkProgram(prog);
    int ok = 0;
    gl->GetProgramiv(prog, 0x8B82, &ok);
    gl->DeleteShader(vsh);
    gl->DeleteShader(fsh);
    if (!ok) { gl->DeleteProgram(prog); return 0; }
    return prog;
}

// Runs the stage over the buffer's first n sprites at clock time (camera-plane facing)
static float *sbCapture(TfGl *gl, GLu prog, RblSpriteBuffer *buf, Camera3D cam, int texW, int texH, float time, int n)
{
    RblCameraFrame view = RblGetCameraFrame(cam);
    RenderTexture2D scratch = LoadRenderTexture(4, 4);
    BeginTextureMode(scratch);
    rlEnableShader(prog);
    rlSetUniformMatrix(rlGetLocationUniform(prog, "mvp"), rbl__identity());
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    float frame[32];
    rbl__instancingFrame(&d, &view, texW, texH, frame);
    frame[28] = 1.0f; frame[29] = time; frame[30] = (float)buf->state->tableWidth; frame[31] = (float)buf->state->frameCount;
    rlSetUniform(rlGetLocationUniform(prog, "rblInstancing"), frame, SHADER_UNIFORM_VEC4, 8);
    int unit = RBL_FRAME_TABLE_TEXTURE_UNIT;
    rlActiveTextureSlot(unit);
    rlEnableTexture(buf->state->tableId);
    rlSetUniform(rlGetLocationUniform(prog, "rblFrameTable"), &unit, SHADER_UNIFORM_INT, 1);
    size_t bytes = (size_t)n*6*SB_TF_FLOATS*sizeof(float);
    GLu tfb = 0;
    gl->GenBuffers(1, &tfb);
    gl->BindBuffer(0x8C8E, tfb);
    gl->BufferData(0x8C8E, (ptrdiff_t)bytes, NULL, 0x88E5);
    gl->BindBufferBase(0x8C8E, 0, tfb);
    rlEnableVertexArray(buf->state->vaoId);
    gl->Enable(0x8C89);
    gl->BeginTransformFeedback(0x0004);
    rlDrawVertexArrayInstanced(0, 6, n);
    gl->EndTransformFeedback();
    gl->Disable(0x8C89);
    rlDisableVertexArray();
    rlDisableTexture();
    rlActiveTextureSlot(0);
    rlDisableShader();
    EndTextureMode();
    UnloadRenderTexture(scratch);
    float *out = (float *)malloc(bytes);
    const void *mapped = gl->MapBufferRange(0x8C8E, 0, (ptrdiff_t)bytes, 0x0001);
    if ((mapped != NULL) && (out != NULL)) memcpy(out, mapped, bytes);
    else if (out != NULL) for (size_t i = 0; i < bytes/sizeof(float); i++) out[i] = NAN;
    if (mapped != NULL) gl->UnmapBuffer(0x8C8E);
    gl->DeleteBuffers(1, &tfb);
    return out;
}

// The GPU's frame, next frame and weight equal the CPU player's (RblUpdateSprite then RblSpriteBlend)
// after every one of 800 steps of 1/64 s, for every tag (every direction, one-frame pingpong, tag
// repeats) x loops (the tag's, forever, 1, 2, 3) x speed (1, 2, 0.5), plus the every-frame tag: each
// sprite of one draw is one (combination, step), its start set back by the step. Durations are
// multiples of 1/8 s: steps land on duration boundaries and loop ends exactly. The quads (per-frame
// trim and pivot) equal RblBillboardVertices of the CPU's frame.
static void test_sprite_buffer_gpu_animation_equals_the_cpu_player_at_every_step(void)
{
    TfGl gl;
    RT_CHECK(tfLoad(&gl), "transform feedback entry points missing");
    GLu prog = sbTfProgram(&gl);
    RT_CHECK(prog != 0, "instanced stage with cross-fade did not link with transform feedback");
    RblAtlas atlas = sbAtlas();
    RT_CHECK(RblIsAtlasValid(atlas), "atlas did not load");
    if ((prog == 0) || !RblIsAtlasValid(atlas)) { if (prog) gl.DeleteProgram(prog); return; }
    enum { STEPS = 800, LOOPS = 5, SPEEDS = 3 };
    const int loopsOf[LOOPS] = { 0, -1, 1, 2, 3 };
    const float speedOf[SPEEDS] = { 1.0f, 2.0f, 0.5f };
    const float dt = 1.0f/64.0f, clock = 37.0f;
    int tags = atlas.tagCount + 1, combos = tags*LOOPS*SPEEDS, n = combos*STEPS;
    RblSpriteBuffer buf = RblLoadSpriteBuffer(&atlas, n);
    RT_CHECK(RblIsSpriteBufferValid(buf), "sprite buffer did not load");
    RblSpriteInstance *sprites = (RblSpriteInstance *)calloc((size_t)n, sizeof(RblSpriteInstance));
    int *cpuFrame = (int *)malloc((size_t)n*sizeof(int)), *cpuNext = (int *)malloc((size_t)n*sizeof(int));
    float *cpuWeight = (float *)malloc((size_t)n*sizeof(float));
    for (int c = 0; c < combos; c++)
    {
        int tag = c/(LOOPS*SPEEDS) - 1, loops = loopsOf[(c/SPEEDS)%LOOPS];
        float speed = speedOf[c%SPEEDS];
        RblSpritePlayer p = RblPlaySprite(&atlas, tag, loops);
        for (int k = 0; k < STEPS; k++)
        {
            int i = c*STEPS + k;
            if (k > 0) RblUpdateSprite(&p, &atlas, dt*speed);
            sprites[i] = RblMakeSprite((Vector3){ 0.25f*(float)(i%40), 0.5f*(float)((i/40)%40), -0.125f*(float)(i%7) }, 1.0f/16.0f, 30.0f*(float)(i%12), 0, WHITE);
            sprites[i].mode = (unsigned short)(i & 3);      // flips about the pivot too
            RblAnimateSprite(&sprites[i], tag, loops, clock - dt*(float)k, speed);
            cpuFrame[i] = p.frame;
            cpuWeight[i] = RblSpriteBlend(&p, &atlas, &cpuNext[i]);
        }
    }
    RT_CHECK(RblUpdateSprites(&buf, 0, n, sprites), "sprites refused");
    Camera3D cam = makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
    float *gpu = sbCapture(&gl, prog, &buf, cam, 64, 64, clock, n);
    RblCameraFrame view = RblGetCameraFrame(cam);
    const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
    int frameOff = 0, nextOff = 0, weightOff = 0, shown = 0;
    double worstPos = 0.0, worstWeight = 0.0, worstRef = 0.0, refScale = 0.0;
    for (int i = 0; i < n; i++)
    {
        RblBillboard b = sbBillboard(&atlas, &sprites[i], cpuFrame[i]), b2 = b;
        b2.source = atlas.frames[cpuNext[i]].source;
        b2.flags = (b.flags & ~(unsigned int)RBL_FRAME_ROTATED) | (atlas.frames[cpuNext[i]].flags & RBL_FRAME_ROTATED);
        RblVertex q[4], q2[4];
        RblBillboardVertices(&view, 64, 64, &b, q);
        RblBillboardVertices(&view, 64, 64, &b2, q2);
        double scale = 1.0 + dLen(d3f(b.position)) + fabs(b.size.x) + fabs(b.size.y);
        bool f = false, nx = false, w;
        for (int v = 0; v < 6; v++)
        {
            const float *g = gpu + ((size_t)i*6 + v)*SB_TF_FLOATS;
            const RblVertex *c = &q[cornerOf[v]], *c2 = &q2[cornerOf[v]];
            for (int k = 0; k < 3; k++) worstPos = fmax(worstPos, fabs(g[k] - c->position[k])/scale);
            for (int k = 0; k < 2; k++) { if (!(fabs(g[3 + k] - c->texcoord[k]) < 1e-5)) f = true; if (!(fabs(g[5 + k] - c2->texcoord[k]) < 1e-5)) nx = true; }
        }
        // the double-precision reference of the decoded sprite (tests/reference.h)
        D3 ref[4], normal;
        refQuad(cam, &b, &ref[0], &normal);
        for (int v = 0; v < 6; v++)
        {
            const float *g = gpu + ((size_t)i*6 + v)*SB_TF_FLOATS;
            worstRef = fmax(worstRef, dLen(dSub(d3(g[0], g[1], g[2]), ref[cornerOf[v]])));
            refScale = fmax(refScale, dLen(ref[cornerOf[v]]));
        }
        double dw = fabs(gpu[(size_t)i*6*SB_TF_FLOATS + 7] - cpuWeight[i]);
        worstWeight = fmax(worstWeight, dw);
        w = !(dw <= 1e-6);
        frameOff += f; nextOff += nx; weightOff += w;
        if ((f || nx || w) && (shown++ < 5))
            printf("    sprite %d (tag %d loops %d speed %g step %d): cpu frame %d next %d weight %g; gpu weight %g, uv (%g, %g)\n", i,
                   (i/STEPS)/(LOOPS*SPEEDS) - 1, loopsOf[((i/STEPS)/SPEEDS)%LOOPS], speedOf[(i/STEPS)%SPEEDS], i%STEPS, cpuFrame[i], cpuNext[i], cpuWeight[i],
                   gpu[(size_t)i*6*SB_TF_FLOATS + 7], gpu[(size_t)i*6*SB_TF_FLOATS + 3], gpu[(size_t)i*6*SB_TF_FLOATS + 4]);
    }
    RT_CHECK(frameOff == 0, "%d of %d sprites show another frame than the CPU player", frameOff, n);
    RT_CHECK(nextOff == 0, "%d of %d sprites fade toward another frame than RblSpriteBlend's", nextOff, n);
    RT_CHECK(weightOff == 0, "%d of %d sprites' weights differ from RblSpriteBlend's by more than 1e-6 (worst %.3g)", weightOff, n, worstWeight);
    RT_CHECK(worstPos < 1e-5, "worst relative corner difference sprite buffer vs RblBillboardVertices %.3g", worstPos);
    RT_CHECK(worstRef/refScale < 4.0*1.1920929e-07, "corner error vs the double reference %.3g (%.3g of the largest corner distance)", worstRef, worstRef/refScale);
    printf("    %d sprite states (%d tag/loop/speed combinations x %d steps): frame, next and weight equal the CPU player; worst weight %.2g, worst relative corner %.2e;"
           " vs the double reference %.3g world units (%.3g rel)\n", n, combos, STEPS, worstWeight, worstPos, worstRef, worstRef/refScale);
    free(gpu); free(sprites); free(cpuFrame); free(cpuNext); free(cpuWeight);
    gl.DeleteProgram(prog);
    RblUnloadSpriteBuffer(&buf);
    RblUnloadAtlas(&atlas);
}

// A sheet whose every texel differs from its neighbours (frames tell apart by colour), opaque
static Texture2D sbSheet(void)
{
    Image img = GenImageColor(64, 64, WHITE);
    for (int y = 0; y < 64; y++) for (int x = 0; x < 64; x++)
        ImageDrawPixel(&img, x, y, (Color){ (unsigned char)(40 + 3*x), (unsigned char)(40 + 3*y), (unsigned char)(((x/4 + y/4) & 1)? 230 : 60), 255 });
    Texture2D t = LoadTextureFromImage(img);
    UnloadImage(img);
    return t;
}

// 2400 sprites in columns over x in [-60, 60): about one in ten in view. Static and animated (every
// tag, flips, rotations), a row of pivots just below the view's bottom edge whose quads reach into
// it. RblDrawSpriteBuffer draws the same pixels as RblDrawInstanced given every sprite as an
// RblInstance set from the CPU player's frame at that clock, yet draws (and returns) only the chunks
// the view can see; turned away it draws nothing and leaves the target as it was.
static void test_sprite_buffer_draw_equals_draw_instanced_and_culls_what_the_view_cannot_see(void)
{
    RblAtlas atlas = sbAtlas();
    Texture2D sheet = sbSheet();
    Material m = sprMaterialOf(sheet, 0.0f, true);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene rejected");
    enum { N = 2400 };
    RblSpriteInstance *s = (RblSpriteInstance *)calloc(N, sizeof(RblSpriteInstance));
    RblInstance *ref = (RblInstance *)calloc(N, sizeof(RblInstance));
    const float clock = 3.25f;
    unsigned int seed = 99u;
    for (int i = 0; i < N; i++)
    {
        // in x order (chunks are spatially coherent, as a game's tiles would be), 24 heights
        float x = -60.0f + 0.05f*(float)i, y = -1.5f + 0.125f*(float)(i%24);
        if (i%24 == 0) y = -2.2f;                                   // pivots below the bottom edge
        s[i] = RblMakeSprite((Vector3){ x, y, -0.001f*(float)(i%13) }, 1.0f/32.0f, (i%5 == 0)? 45.0f*(float)(i%8) : 0.0f, (int)(rtRandom(&seed)%7u), WHITE);
        s[i].mode = (unsigned short)(rtRandom(&seed) & 3u);
        int frame = s[i].frame;
        if (i%3 != 0)
        {
            int tag = (int)(rtRandom(&seed)%9u) - 1, loops = (i%4 == 0)? 2 : -1;
            float start = 0.125f*(float)(rtRandom(&seed)%16u), speed = (i%2)? 1.0f : 2.0f;
            RblAnimateSprite(&s[i], tag, loops, start, speed);
            RblSpritePlayer p = RblPlaySprite(&atlas, tag, loops);
            RblUpdateSprite(&p, &atlas, (clock - start)*speed);
            frame = p.frame;
        }
        RblBillboard b = sbBillboard(&atlas, &s[i], frame);
        ref[i] = sbInstance(&b);
    }
    RblSpriteBuffer buf = RblLoadSpriteBuffer(&atlas, N);
    RT_CHECK(RblUpdateSprites(&buf, 0, N, s) && (buf.count == N), "sprites refused (count %d)", buf.count);
    RblInstanceBuffer ib = RblLoadInstanceBuffer(N);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    Camera3D cam = frontCamera();
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    int drawn = RblDrawSpriteBuffer(&buf, cam, m, d, clock);
    EndMode3D(); EndTextureMode();
    Image a = rtReadTarget(rt);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    int all = RblDrawInstanced(&ib, cam, m, d, ref, N);
    EndMode3D(); EndTextureMode();
    Image b = rtReadTarget(rt);
    int lit = 0, off = 0, bottom = 0;
    for (int y = 0; y < TARGET; y++) for (int x = 0; x < TARGET; x++)
    {
        Color ca = rtPixel(a, x, y), cb = rtPixel(b, x, y);
        if (cb.r > 0) { lit++; if (y >= TARGET - 3) bottom++; }
        if ((ca.r != cb.r) || (ca.g != cb.g) || (ca.b != cb.b)) off++;
    }
    RT_CHECK(all == N, "reference drew %d of %d", all, N);
    RT_CHECK(lit > TARGET*TARGET/4, "reference nearly empty (%d lit)", lit);
    RT_CHECK(bottom > 0, "no quad reaches the bottom edge: the straddling row is not exercised");
    RT_CHECK(off == 0, "%d pixels differ between the sprite buffer and RblDrawInstanced", off);
    // The view spans about 4.1 units of the 120: 10 of the 2400 sprites' chunks, plus at most two partly seen
    RT_CHECK((drawn > 0) && (drawn <= N/10 + 2*256), "drawn %d of %d: culling by chunk should leave about one in ten", drawn, N);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(a, "sprite_buffer"); rtSaveImage(b, "sprite_buffer_reference"); }
    // Turned away: nothing drawn, nothing written
    Camera3D away = cam;
    away.target = (Vector3){ 0.0f, 0.0f, 10.0f };
    BeginTextureMode(rt); BeginMode3D(away);
    int none = RblDrawSpriteBuffer(&buf, away, m, d, clock);
    EndMode3D(); EndTextureMode();
    Image c = rtReadTarget(rt);
    int changed = 0;
    for (int y = 0; y < TARGET; y++) for (int x = 0; x < TARGET; x++) { Color cb = rtPixel(b, x, y), cc = rtPixel(c, x, y); changed += (cb.r != cc.r) || (cb.g != cc.g) || (cb.b != cc.b); }
    RT_CHECK((none == 0) && (changed == 0), "turned away: drew %d sprites, %d pixels changed", none, changed);
    printf("    sprite buffer vs RblDrawInstanced: %d pixels differ; culling drew %d of %d sprites (the view sees about %d %%)\n", off, drawn, N, 100*drawn/N);
    UnloadImage(a); UnloadImage(b); UnloadImage(c);
    UnloadRenderTexture(rt);
    RblUnloadInstanceBuffer(&ib);
    RblUnloadSpriteBuffer(&buf);
    free(s); free(ref);
    sprUnloadMaterial(&m);
    UnloadTexture(sheet);
    RblUnloadAtlas(&atlas);
}

// Ranges: an update of one sprite changes its pixels only (the image equals RblDrawInstanced of the
// new set), a range holding one bad sprite is refused whole with one line and changes nothing, and
// the resident set draws the same every frame without being touched. ES 2 / GL 2.1: refused with
// one line, the zeroed result unloads with one more.
static void test_sprite_buffer_range_updates_change_only_their_sprites(void)
{
    RblAtlas atlas = sbAtlas();
    if (!rtGlsl3())
    {
        warnings = 0;
        RblSpriteBuffer none = RblLoadSpriteBuffer(&atlas, 4);
        RT_CHECK(!RblIsSpriteBufferValid(none) && (warnings == 1), "sprite buffer on a GLSL 1 context: %d log lines, want 1", warnings);
        warnings = 0;
        RblUnloadSpriteBuffer(&none);
        RT_CHECK(warnings == 1, "unloading the refused sprite buffer: %d log lines, want 1", warnings);
        RblUnloadAtlas(&atlas);
        return;
    }
    Texture2D sheet = sbSheet();
    Material m = sprMaterialOf(sheet, 0.0f, true);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene rejected");
    RblSpriteInstance s[3];
    for (int i = 0; i < 3; i++) s[i] = RblMakeSprite((Vector3){ -1.2f + 1.2f*(float)i, -0.5f, 0.0f }, 1.0f/16.0f, 0.0f, i, WHITE);
    RblSpriteBuffer buf = RblLoadSpriteBuffer(&atlas, 3);
    RT_CHECK(RblUpdateSprites(&buf, 0, 3, s), "sprites refused");
    RblInstanceBuffer ib = RblLoadInstanceBuffer(3);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    Camera3D cam = frontCamera();
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    Image img[5];
    for (int k = 0; k < 5; k++)
    {
        if (k == 2) { RblSpriteInstance one = s[1]; one.frame = 4; one.mode = RBL_SPRITE_FLIP_X; RT_CHECK(RblUpdateSprites(&buf, 1, 1, &one), "one sprite refused"); s[1] = one; }
        if (k == 3)
        {
            RblSpriteInstance bad[3] = { s[2], s[1], s[0] };
            bad[2].position.y = NAN;
            warnings = 0;
            RT_CHECK(!RblUpdateSprites(&buf, 0, 3, bad) && (warnings == 1), "a range with a NaN sprite: accepted or %d lines", warnings);
        }
        BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
        if (k < 4) RblDrawSpriteBuffer(&buf, cam, m, d, 0.0f);
        else
        {
            RblInstance in[3];
            for (int i = 0; i < 3; i++) { RblBillboard b = sbBillboard(&atlas, &s[i], s[i].frame); in[i] = sbInstance(&b); }
            RblDrawInstanced(&ib, cam, m, d, in, 3);
        }
        EndMode3D(); EndTextureMode();
        img[k] = rtReadTarget(rt);
    }
    int same01 = 0, changedOutside = 0, changedInside = 0, same23 = 0, same24 = 0, lit = 0;
    for (int y = 0; y < TARGET; y++) for (int x = 0; x < TARGET; x++)
    {
        Color c0 = rtPixel(img[0], x, y), c1 = rtPixel(img[1], x, y), c2 = rtPixel(img[2], x, y), c3 = rtPixel(img[3], x, y), c4 = rtPixel(img[4], x, y);
        same01 += (c0.r == c1.r) && (c0.g == c1.g) && (c0.b == c1.b);
        same23 += (c2.r == c3.r) && (c2.g == c3.g) && (c2.b == c3.b);
        same24 += (c2.r == c4.r) && (c2.g == c4.g) && (c2.b == c4.b);
        bool diff = (c0.r != c2.r) || (c0.g != c2.g) || (c0.b != c2.b);
        bool middle = (x >= TARGET/3) && (x < 2*TARGET/3);
        if (diff) { if (middle) changedInside++; else changedOutside++; }
        lit += c0.r > 0;
    }
    RT_CHECK(lit > 100, "nothing drawn (%d lit)", lit);
    RT_CHECK(same01 == TARGET*TARGET, "an untouched resident set drew differently the next frame (%d pixels)", TARGET*TARGET - same01);
    RT_CHECK((changedInside > 20) && (changedOutside == 0), "updating sprite 1 changed %d pixels around it and %d elsewhere", changedInside, changedOutside);
    RT_CHECK(same23 == TARGET*TARGET, "a refused update changed %d pixels", TARGET*TARGET - same23);
    RT_CHECK(same24 == TARGET*TARGET, "%d pixels differ from RblDrawInstanced of the updated set", TARGET*TARGET - same24);
    if (rtFailuresInCurrentTest() > 0) for (int k = 0; k < 5; k++) { char name[24]; snprintf(name, sizeof(name), "range_%d", k); rtSaveImage(img[k], name); }
    for (int k = 0; k < 5; k++) UnloadImage(img[k]);
    UnloadRenderTexture(rt);
    RblUnloadInstanceBuffer(&ib);
    RblUnloadSpriteBuffer(&buf);
    sprUnloadMaterial(&m);
    UnloadTexture(sheet);
    RblUnloadAtlas(&atlas);
}

// Quantisation of the 32-byte sprite: rotation to 360/65536 degrees (error at most half a step over
// a sweep of angles, negative and beyond a turn included), speed to a half float (relative error
// at most 2^-11 over its normal range, subnormals to 2^-25 absolute); position and scale are stored
// as given (float)
static void test_sprite_buffer_quantisation_is_within_half_a_step(void)
{
    double worstRot = 0.0, worstSpeed = 0.0, worstSub = 0.0;
    for (int i = -20000; i <= 20000; i++)
    {
        float deg = 0.0371f*(float)i;
        RblSpriteInstance s = RblMakeSprite((Vector3){ 1.5f, -2.25f, 3.0f }, 0.3f, deg, 0, WHITE);
        double back = (double)s.rotation*(360.0/65536.0), want = fmod((double)deg, 360.0);
        if (want < 0.0) want += 360.0;
        double e = fabs(back - want);
        if (e > 180.0) e = 360.0 - e;
        worstRot = fmax(worstRot, e);
        RT_CHECK((s.position.x == 1.5f) && (s.position.y == -2.25f) && (s.position.z == 3.0f) && (s.scale == 0.3f), "position or scale not kept exactly");
    }
    for (int i = 0; i <= 4000; i++)
    {
        float speed = (i < 2000)? 6.1035156e-05f*powf(2.0f, (float)i/2000.0f*30.0f) : 6.1035156e-05f*(float)(i - 2000)/2000.0f;
        if (speed > 65504.0f) continue;
        RblSpriteInstance s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, 0.0f, 0, WHITE);
        RT_CHECK(RblAnimateSprite(&s, -1, -1, 0.0f, speed), "speed %g refused", speed);
        unsigned int h = s.speed, e = (h >> 10) & 31u, mant = h & 1023u;
        double v = (e == 0u)? mant*ldexp(1.0, -24) : ldexp(1.0 + mant/1024.0, (int)e - 15);
        if (speed >= 6.1035156e-05f) worstSpeed = fmax(worstSpeed, fabs(v - speed)/speed);
        else worstSub = fmax(worstSub, fabs(v - speed));
    }
    RT_CHECK(worstRot <= 180.0/65536.0 + 1e-9, "rotation off by %.3g degrees (half a step is %.3g)", worstRot, 180.0/65536.0);
    RT_CHECK(worstSpeed <= ldexp(1.0, -11) + 1e-12, "speed off by %.3g relative (half a half-float step is %.3g)", worstSpeed, ldexp(1.0, -11));
    RT_CHECK(worstSub <= ldexp(1.0, -25) + 1e-15, "subnormal speed off by %.3g (half a step is %.3g)", worstSub, ldexp(1.0, -25));
    printf("    rotation within %.3g degrees (step 360/65536), speed within %.3g relative (%.3g absolute below 2^-14); position and scale exact\n", worstRot, worstSpeed, worstSub);
}

// In a shadow pass a sprite buffer casts through the caster program's resident-sprite variant (its
// depth code set for the pass): the holed card of test_shadows' hole test, as one resident sprite,
// shades the floor exactly as RblDrawInstanced's card does, hole included
static const char sbCardAtlasText[] = "{\"frames\": [{\"filename\": \"card\", \"frame\": {\"x\":0,\"y\":0,\"w\":64,\"h\":64}, \"pivot\": {\"x\":0.5,\"y\":0.5}}], \"meta\": {\"size\": {\"w\":64,\"h\":64}}}";
static void sbCardCaster(Material m, Camera3D viewer, void *ctx)
{
    int *drawn = (int *)ctx;
    RblAtlas atlas = RblLoadAtlasFromMemory(sbCardAtlasText, (int)strlen(sbCardAtlasText), RBL_ATLAS_AUTO);
    RblSpriteBuffer buf = RblLoadSpriteBuffer(&atlas, 2);
    RblSpriteInstance s[2] = { RblMakeSprite((Vector3){ 0.0f, 0.0f, 1.0f }, 2.0f/64.0f, 0.0f, 0, WHITE),
                               RblMakeSprite((Vector3){ 500.0f, 0.0f, 1.0f }, 2.0f/64.0f, 0.0f, 0, WHITE) };     // far outside the light's focus
    RblUpdateSprites(&buf, 0, 1, &s[0]);
    RblUpdateSprites(&buf, 300, 0, NULL);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.facing = RBL_FACING_FIXED; d.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; d.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    *drawn = RblDrawSpriteBuffer(&buf, viewer, m, d, 0.0f);
    RblUnloadSpriteBuffer(&buf);
    RblUnloadAtlas(&atlas);
}

static void test_sprite_buffer_casts_the_shadow_draw_instanced_casts(void)
{
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    s.lights[0].direction = (Vector3){ 0.4f, 0.0f, -1.0f };
    Image img = GenImageColor(64, 64, WHITE);
    ImageDrawCircle(&img, 32, 32, 14, BLANK);
    Texture2D holed = LoadTextureFromImage(img);
    UnloadImage(img);
    ShCard card = { { 0.0f, 0.0f, 1.0f }, 2.0f, 2 };
    Image ref = shRender(&s, shCardCasters, &card, holed, false);
    int drawn = -1;
    Image out = shRender(&s, sbCardCaster, &drawn, holed, false);
    int off = 0;
    for (int y = 0; y < SH_TARGET; y++) for (int x = 0; x < SH_TARGET; x++) off += abs(rtPixel(out, x, y).r - rtPixel(ref, x, y).r) > 1;
    int cx = (int)((0.4f + SH_VIEW*0.5f)/SH_VIEW*SH_TARGET), cy = SH_TARGET/2;
    int hole = rtPixel(out, cx, cy).r, ring = rtPixel(out, cx + 11, cy).r, outside = rtPixel(out, cx + 24, cy).r;
    RT_CHECK(drawn == 1, "shadow pass drew %d resident sprites, want 1", drawn);
    RT_CHECK(hole > outside - 3 && ring < outside - 40, "hole %d, ring %d, unshadowed %d: the sprite's shadow (and its hole) missing", hole, ring, outside);
    RT_CHECK(off == 0, "%d floor pixels differ by more than 1/255 from RblDrawInstanced's shadow", off);
    printf("    resident sprite's shadow: hole %d, ring %d, unshadowed %d; %d pixels off RblDrawInstanced's\n", hole, ring, outside, off);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(out, "sprite_shadow"); rtSaveImage(ref, "instanced_shadow"); }
    UnloadImage(out); UnloadImage(ref);
    UnloadTexture(holed);
}

// RblUpdateSprites writing a whole buffer through a fresh mapped store equals the upload (test hook
// spriteNoMap) and a CPU model: 100 updates of the whole buffer, ranges across chunks, parts of one
// chunk, single sprites and nothing, every fifth holding one bad sprite (refused with one line,
// nothing changed); after each: the GPU buffers read back bit for bit, the pivot copy, every chunk's
// bounds against one sprite at a time over the model (hidden sprites, +/-0 pivots), the counts.
static void test_sprite_buffer_mapped_update_equals_the_upload_and_a_model(void)
{
    RblAtlas atlas = sbAtlas();
    enum { N = 7*RBL__SPRITE_CHUNK - 45, STEPS = 100 };
    RblSpriteBuffer buf[2] = { RblLoadSpriteBuffer(&atlas, N), RblLoadSpriteBuffer(&atlas, N) };
    RblSpriteInstance *model = (RblSpriteInstance *)calloc(N, sizeof(RblSpriteInstance)), *in = (RblSpriteInstance *)calloc(N, sizeof(RblSpriteInstance));
    float *pivots = (float *)calloc((size_t)N*4, sizeof(float)), *bounds = (float *)calloc((size_t)N*7, sizeof(float));
    if (!RblIsSpriteBufferValid(buf[0]) || !RblIsSpriteBufferValid(buf[1]) || (model == NULL) || (in == NULL) || (pivots == NULL) || (bounds == NULL))
    {
        RT_CHECK(false, "set-up failed");
        RblUnloadSpriteBuffer(&buf[0]); RblUnloadSpriteBuffer(&buf[1]); free(model); free(in); free(pivots); free(bounds); RblUnloadAtlas(&atlas);
        return;
    }
    const bool maps = rbl__canMap();
    const long long mappedBefore = rbl__state.spriteMapped;
    const float coords[] = { 0.0f, -0.0f, 3.5f, -3.5f };
    unsigned int seed = 4242u;
    int modelCount = 0, wrong = 0, refused = 0, readBack = 0;
    for (int step = 0; step < STEPS; step++)
    {
        int kind = step%5, first = 0, count = N;
        if (kind == 1) { first = (int)(rtRandom(&seed)%(unsigned int)N); count = (int)(rtRandom(&seed)%(unsigned int)(N - first + 1)); }
        if (kind == 2) { first = (int)(rtRandom(&seed)%(unsigned int)N); count = (int)(rtRandom(&seed)%(unsigned int)(RBL__SPRITE_CHUNK - first%RBL__SPRITE_CHUNK)) + 1; if (count > N - first) count = N - first; }
        if (kind == 3) { first = (int)(rtRandom(&seed)%(unsigned int)N); count = (step%10 == 3)? 0 : 1; }
        for (int i = 0; i < count; i++)
        {
            Vector3 p = { rtRandomRange(&seed, -20.0f, 20.0f), rtRandomRange(&seed, -20.0f, 20.0f), rtRandomRange(&seed, -20.0f, 20.0f) };
            for (int k = 0; k < 3; k++) if (rtRandom(&seed)%4u == 0u) ((float *)&p)[k] = coords[rtRandom(&seed)%4u];
            unsigned int h = rtRandom(&seed)%6u;
            float scale = (h == 0)? 0.0f : (h == 1)? -0.0f : rtRandomRange(&seed, 0.001f, 2.0f);
            in[i] = RblMakeSprite(p, scale, 7.5f*(float)(rtRandom(&seed)%48u), (int)(rtRandom(&seed)%7u), (Color){ (unsigned char)rtRandom(&seed), 0, 0, 255 });
            if (h == 1) in[i].scale = -0.0f;
            if (rtRandom(&seed)%3u == 0u) RblAnimateSprite(&in[i], (int)(rtRandom(&seed)%9u) - 1, (int)(rtRandom(&seed)%4u) - 1, rtRandomRange(&seed, -3.0f, 3.0f), rtRandomRange(&seed, 0.0f, 4.0f));
            in[i].mode = (unsigned short)(in[i].mode | (rtRandom(&seed) & 3u));
        }
        const bool bad = (step%5 == 4) && (count > 0);
        if (bad)
        {
            int at = (int)(rtRandom(&seed)%(unsigned int)count);
            if (step%10 == 4) in[at].position.z = NAN; else { in[at].mode = (unsigned short)(in[at].mode & ~RBL_SPRITE_ANIMATED); in[at].frame = 7; }     // NaN, or a frame the atlas has not
        }
        bool ok[2];
        int lines[2];
        for (int v = 0; v < 2; v++)
        {
            rbl__state.spriteNoMap = (v == 1);
            warnings = 0;
            ok[v] = RblUpdateSprites(&buf[v], first, count, in);
            lines[v] = warnings;
        }
        rbl__state.spriteNoMap = false;
        if (!bad)
        {
            memcpy(model + first, in, (size_t)count*sizeof(RblSpriteInstance));
            if ((count > 0) && (first + count > modelCount)) modelCount = first + count;
        }
        refused += bad;
        // The model's pivots and chunk bounds, one sprite at a time
        for (int i = 0; i < N; i++) { pivots[4*i] = model[i].position.x; pivots[4*i + 1] = model[i].position.y; pivots[4*i + 2] = model[i].position.z; pivots[4*i + 3] = model[i].scale; }
        const int chunks = (N + RBL__SPRITE_CHUNK - 1)/RBL__SPRITE_CHUNK;
        for (int c = 0; c < chunks; c++) rbl__spriteChunkBoundsScalar(pivots, bounds, modelCount, c);
        for (int v = 0; v < 2; v++)
        {
            const rbl__SpriteBufferState *st = rbl__spriteState(&buf[v]);
            bool same = (ok[v] == !bad) && (lines[v] == (bad? 1 : 0)) && (buf[v].count == modelCount) && (st != NULL) && (st->count == modelCount);
            same = same && (memcmp(st->pivots, pivots, (size_t)N*4*sizeof(float)) == 0);
            for (int c = 0; same && (c < chunks); c++) same = memcmp(st->bounds + 7*c, bounds + 7*c, ((bounds[7*c + 6] >= 0.0f)? 7 : 1)*sizeof(float)) == 0;
            if (same && maps)
            {
                const void *p = rbl__mapBuffer(st->vboId, (size_t)N*sizeof(RblSpriteInstance), true);
                same = (p != NULL) && (memcmp(p, model, (size_t)N*sizeof(RblSpriteInstance)) == 0);
                same = rbl__unmapBuffer(st->vboId) && same;
                readBack++;
            }
            if (!same && (wrong++ < 5)) RT_CHECK(false, "step %d (%s first %d count %d%s): returned %d, %d lines, count %d / %d", step, v? "uploaded" : "mapped", first, count, bad? ", one bad" : "",
                                                 (int)ok[v], lines[v], buf[v].count, modelCount);
        }
    }
    const long long mapped = rbl__state.spriteMapped - mappedBefore;
    printf("    %d updates x 2 buffers: %d wrong, %d refused, %d read back, %lld written through the mapped store%s\n", STEPS, wrong, refused, readBack, mapped, maps? "" : " (no mapping here)");
    RT_CHECK(wrong == 0, "%d updates differ from the model", wrong);
    RT_CHECK(!maps || ((readBack == 2*STEPS) && (mapped >= STEPS/5 - 2)), "mapped path not exercised: %d read back, %lld mapped", readBack, mapped);
    RblUnloadSpriteBuffer(&buf[0]); RblUnloadSpriteBuffer(&buf[1]);
    free(model); free(in); free(pivots); free(bounds);
    RblUnloadAtlas(&atlas);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_SPRITE_BUFFER_TESTS \
    RT_TEST_GLSL3(test_sprite_buffer_gpu_animation_equals_the_cpu_player_at_every_step), \
    RT_TEST_GLSL3(test_sprite_buffer_draw_equals_draw_instanced_and_culls_what_the_view_cannot_see), \
    RT_TEST(test_sprite_buffer_range_updates_change_only_their_sprites), \
    RT_TEST(test_sprite_buffer_quantisation_is_within_half_a_step), \
    RT_TEST_GLSL3(test_sprite_buffer_casts_the_shadow_draw_instanced_casts), \
    RT_TEST_GLSL3(test_sprite_buffer_mapped_update_equals_the_upload_and_a_model)
