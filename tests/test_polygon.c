// Polygon frames (TexturePacker polygon packing) drawn as their polygons on every path: the batch, the
// immediate path, instanced draws, resident sprite buffers, shadow casters and the G-buffer. Each draw
// is compared pixel by pixel with the same frame drawn as its quad (the polygon bits cleared) and with a
// double-precision CPU rasterisation of the hand-derived polygon (polygon_fixture.h): a pixel whose
// centre lies inside the polygon (by 0.02 frame pixels) equals the quad's, one outside it is not drawn.
// Orthographic camera, 8 screen pixels per texel. Included by gpu_tests.h.
#include "polygon_fixture.h"

#define POLY_RT 256
#define POLY_SCALE 8.0f
enum { POLY_BATCH = 0, POLY_IMMEDIATE, POLY_INSTANCED, POLY_SPRITES, POLY_PATHS };
static const char *const polyPathNames[POLY_PATHS] = { "batch", "immediate", "instanced", "sprite buffer" };

static Camera3D polyCamera(void)
{
    Camera3D cam; memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0, 0, 10 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = (float)POLY_RT; cam.projection = CAMERA_ORTHOGRAPHIC;
    return cam;
}

// Opaque noise sheet (no texel equals the clear colour)
static Image polySheet(void)
{
    Image img = GenImageColor(POLY_SHEET, POLY_SHEET, BLACK);
    Color *px = (Color *)img.data;
    unsigned int seed = 1234u;
    for (int i = 0; i < POLY_SHEET*POLY_SHEET; i++)
    {
        unsigned int r = rtRandom(&seed);
        px[i] = (Color){ (unsigned char)(64 + (r & 127)), (unsigned char)(64 + ((r >> 8) & 127)), (unsigned char)(64 + ((r >> 16) & 127)), 255 };
    }
    return img;
}

static const Color polyClear = { 0, 0, 255, 255 };

// The instance of a billboard (facing shared by the draw)
static RblInstance polyInstance(const RblBillboard *b)
{
    RblInstance in; memset(&in, 0, sizeof(in));
    in.position = b->position; in.rotation = b->rotation; in.size = b->size; in.origin = b->origin; in.source = b->source; in.tint = b->tint; in.flags = b->flags;
    return in;
}

// Draws billboard b (frame k of atlas a) on one path into rt; the colour of what it drew
static Image polyDraw(RenderTexture2D rt, Material m, const RblAtlas *a, int k, const RblBillboard *b, int path)
{
    Camera3D cam = polyCamera();
    BeginTextureMode(rt); ClearBackground(polyClear); BeginMode3D(cam);
    if (path == POLY_BATCH)
    {
        RblBatch batch = RblLoadBatch(0);
        RblBeginBatch(&batch, cam);
        RT_CHECK(RblBatchAdd(&batch, m, b), "batch add");
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
    }
    else if (path == POLY_IMMEDIATE) RblDrawBillboard(cam, m, *b);
    else if (path == POLY_INSTANCED)
    {
        RblInstanceBuffer buf = RblLoadInstanceBuffer(0);
        RblInstance in = polyInstance(b);
        RblInstancedDesc desc; memset(&desc, 0, sizeof(desc));
        desc.facing = b->facing; desc.roundness = b->roundness;
        RT_CHECK(RblDrawInstanced(&buf, cam, m, desc, &in, 1) == 1, "instanced draw");
        RblUnloadInstanceBuffer(&buf);
    }
    else
    {
        RblSpriteBuffer sb = RblLoadSpriteBuffer(a, 1);
        RblSpriteInstance s = RblMakeSprite(b->position, POLY_SCALE, b->rotation, k, BLANK);
        if (b->size.x < 0) s.mode |= RBL_SPRITE_FLIP_X;
        if (b->size.y < 0) s.mode |= RBL_SPRITE_FLIP_Y;
        RT_CHECK(RblUpdateSprites(&sb, 0, 1, &s), "sprite update");
        RblInstancedDesc desc; memset(&desc, 0, sizeof(desc));
        desc.facing = b->facing; desc.roundness = b->roundness;
        RT_CHECK(RblDrawSpriteBuffer(&sb, cam, m, desc, 0.0f) >= 1, "sprite draw");
        RblUnloadSpriteBuffer(&sb);
    }
    EndMode3D(); EndTextureMode();
    return rtReadTarget(rt);
}

// Where screen pixel (px, py) falls in billboard b's upright trimmed picture (pixels from its
// top-left), in double precision; false outside the quad
static bool polyPicturePoint(const RblBillboard *b, const RblAtlasFrame *f, int px, int py, double *x, double *y)
{
    double wx = px + 0.5 - POLY_RT/2.0, wy = POLY_RT/2.0 - (py + 0.5);
    double dx = wx - b->position.x, dy = wy - b->position.y, th = b->rotation*3.14159265358979323846/180.0;
    double rx = dx*cos(th) + dy*sin(th), ry = -dx*sin(th) + dy*cos(th);
    double s = (rx + b->origin.x)/fabs(b->size.x), up = (ry + b->origin.y)/fabs(b->size.y), t = 1.0 - up;
    if (b->size.x < 0) s = 1.0 - s;
    if (b->size.y < 0) t = 1.0 - t;
    *x = s*f->trim.width; *y = t*f->trim.height;
    return (s >= 0.0) && (s <= 1.0) && (t >= 0.0) && (t <= 1.0);
}

typedef struct PolyCount { int inside, outside, cutByQuad, badInside, badOutside, badBeyond, drawn, worst, tolerance, ties; double edgeFar; } PolyCount;

// A pixel centre this near a texel edge (in texels) samples whichever texel its interpolated
// texcoord rounds to, so it is not compared. llvmpipe's texcoords hold 1e-3 texels here; the
// browser's SwiftShader interpolates less exactly (test_raster_interpolated_position_...'s n/a line):
// its differing pixels lie within 0.0017 texels of an edge, so the band there is 0.004
static double polyTieTexels(void)
{
#ifdef __EMSCRIPTEN__
    return 4e-3;
#else
    return 1e-3;
#endif
}

// The polygon draw against the quad draw and the CPU rasterisation
static void polyCompare(Image quad, Image poly, int k, const RblBillboard *b, const RblAtlasFrame *f, PolyCount *c)
{
    const Color *q = (const Color *)quad.data, *p = (const Color *)poly.data;
    for (int py = 0; py < POLY_RT; py++)
        for (int px = 0; px < POLY_RT; px++)
        {
            int i = py*POLY_RT + px;
            bool clearP = (p[i].r == polyClear.r) && (p[i].g == polyClear.g) && (p[i].b == polyClear.b);
            bool clearQ = (q[i].r == polyClear.r) && (q[i].g == polyClear.g) && (q[i].b == polyClear.b);
            c->drawn += !clearP;
            double x, y;
            if (!polyPicturePoint(b, f, px, py, &x, &y)) { c->badBeyond += !clearP; continue; }
            bool tie = (fabs(x - floor(x + 0.5)) < polyTieTexels()) || (fabs(y - floor(y + 0.5)) < polyTieTexels());
            c->ties += tie && polyFixtureInside(k, x, y, 0.02);
            if (polyFixtureInside(k, x, y, 0.02) && !tie)
            {
                c->inside++;
                int d = abs(p[i].r - q[i].r);
                if (abs(p[i].g - q[i].g) > d) d = abs(p[i].g - q[i].g);
                if (abs(p[i].b - q[i].b) > d) d = abs(p[i].b - q[i].b);
                if (abs(p[i].a - q[i].a) > d) d = abs(p[i].a - q[i].a);
                if (d > c->worst) c->worst = d;
                bool differs = clearP || (d > c->tolerance);
                if (differs && (getenv("RBL_POLY_LOOK") != NULL)) printf("      differs at %d,%d (frame %g,%g): %d %d %d vs %d %d %d\n", px, py, x, y, p[i].r, p[i].g, p[i].b, q[i].r, q[i].g, q[i].b);
                c->badInside += differs;
                double edge = fmin(fabs(x - floor(x + 0.5)), fabs(y - floor(y + 0.5)));     // texels to the nearest texel edge
                if (differs && (edge > c->edgeFar)) c->edgeFar = edge;
            }
            else if (polyFixtureInside(k, x, y, -0.02))
            {
                c->outside++;
                c->cutByQuad += !clearQ;
                c->badOutside += !clearP;
            }
        }
}

// The frames one after another on a path, each plain, mirrored both ways and turned; the counts
static PolyCount polyRunPath(int path, Material m, const RblAtlas *a, int *draws, float roundness, int tolerance)
{
    PolyCount c; memset(&c, 0, sizeof(c));
    c.tolerance = tolerance;
    RenderTexture2D rt = LoadRenderTexture(POLY_RT, POLY_RT);
    for (int k = 0; k < 3; k++)
        for (int v = 0; v < 4; v++)
        {
            RblBillboard b; memset(&b, 0, sizeof(b));
            RT_CHECK(RblAtlasBillboard(a, k, POLY_SCALE, &b), "billboard");
            b.position = (Vector3){ 3.0f, -5.0f, 0.0f };
            b.roundness = roundness;
            if (v & 1) { b.size.x = -b.size.x; b.size.y = -b.size.y; }
            if (v & 2) b.rotation = 45.0f;       // exact in a sprite's 65536ths of a turn
            if (path == POLY_SPRITES)
            {
                // a sprite mirrors about its pivot: the quad moves (origin follows)
                if (v & 1) { b.origin.x = -b.size.x - b.origin.x; b.origin.y = -b.size.y - b.origin.y; }
            }
            RblBillboard plain = b;
            plain.flags &= ~(unsigned int)RBL_FRAME_POLYGON;
            Image quad = polyDraw(rt, m, a, k, &plain, (path == POLY_SPRITES)? POLY_INSTANCED : path);
            Image poly = polyDraw(rt, m, a, k, &b, path);
            PolyCount before = c;
            c.worst = 0;
            polyCompare(quad, poly, k, &b, &a->frames[k], &c);
            if (getenv("RBL_POLY_LOOK") != NULL) printf("      frame %d v %d: worst %d\n", k, v, c.worst);
            if (before.worst > c.worst) c.worst = before.worst;
            if ((c.badInside != before.badInside) || (c.badOutside != before.badOutside) || (c.badBeyond != before.badBeyond) || (getenv("RBL_POLY_LOOK") != NULL))
            {
                char tag[64];
                snprintf(tag, sizeof(tag), "%s-frame%d-v%d-quad", polyPathNames[path], k, v); rtSaveImage(quad, tag);
                snprintf(tag, sizeof(tag), "%s-frame%d-v%d-polygon", polyPathNames[path], k, v); rtSaveImage(poly, tag);
            }
            UnloadImage(quad); UnloadImage(poly);
            (*draws)++;
        }
    UnloadRenderTexture(rt);
    return c;
}

static void polyMaterial(Material *m, Texture2D tex, bool instanced, Shader *lit)
{
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.instanced = instanced;
    *lit = RblLoadLitShader(desc);
    *m = LoadMaterialDefault();
    m->shader = *lit;
    m->maps[MATERIAL_MAP_ALBEDO].texture = tex;
}

static void polyCheckPath(int path)
{
    RblAtlas a = RblLoadAtlasFromMemory(polyFixture, (int)strlen(polyFixture), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(a) && a.frameCount == 3, "fixture");
    if (!RblIsAtlasValid(a)) return;
    Image sheet = polySheet();
    Texture2D tex = LoadTextureFromImage(sheet);
    Shader lit; Material m;
    polyMaterial(&m, tex, path >= POLY_INSTANCED, &lit);
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    int draws = 0;
    PolyCount c = polyRunPath(path, m, &a, &draws, 0.0f, 0);
    printf("    %s: %d draws; %d pixels inside the polygons equal the quad's (%d differ, the farthest %.2g texels from a texel edge; %d within %.0e texels of one not compared), %d cut-away pixels the quad drew left undrawn (%d drawn)\n",
           polyPathNames[path], draws, c.inside - c.badInside, c.badInside, c.edgeFar, c.ties, polyTieTexels(), c.cutByQuad, c.badOutside);
    RT_CHECK(c.inside > 20000 && c.badInside == 0, "%s: %d of %d inside pixels differ from the quad's", polyPathNames[path], c.badInside, c.inside);
    RT_CHECK(c.cutByQuad > 20000 && c.badOutside == 0 && c.badBeyond == 0, "%s: %d cut-away pixels drawn (the quad drew %d of them), %d beyond the quad", polyPathNames[path], c.badOutside, c.cutByQuad, c.badBeyond);
    RblUnloadLitShader(&lit);
    UnloadTexture(tex); UnloadImage(sheet);
    MemFree(m.maps);
    RblUnloadAtlas(&a);
}

static void test_polygon_batch_draws_the_polygon_and_none_of_the_cut_away_quad(void) { polyCheckPath(POLY_BATCH); }
static void test_polygon_immediate_draws_the_polygon_and_none_of_the_cut_away_quad(void) { polyCheckPath(POLY_IMMEDIATE); }

static void test_polygon_instanced_draws_the_polygon_and_none_of_the_cut_away_quad(void) { polyCheckPath(POLY_INSTANCED); }

// A smooth normal map (tilts varying over a few texels, unit vectors in RGB)
static Image polyNormalMap(void)
{
    Image img = GenImageColor(POLY_SHEET, POLY_SHEET, BLACK);
    Color *px = (Color *)img.data;
    for (int y = 0; y < POLY_SHEET; y++)
        for (int x = 0; x < POLY_SHEET; x++)
        {
            double nx = 0.5*sin(x*0.7 + y*0.3), ny = 0.5*cos(x*0.2 - y*0.9), nz = sqrt(fmax(0.0, 1.0 - nx*nx - ny*ny));
            px[y*POLY_SHEET + x] = (Color){ (unsigned char)lround((nx*0.5 + 0.5)*255.0), (unsigned char)lround((ny*0.5 + 0.5)*255.0), (unsigned char)lround((nz*0.5 + 0.5)*255.0), 255 };
        }
    return img;
}

// Lit by a directional light from the side with a normal map, flat (roundness 0) and rounded (0.6,
// sphere): the polygon's pixels are the quad's (its normals and tangents are the quad's fields)
static void test_polygon_lit_normal_mapped_pixels_equal_the_quads_flat_and_rounded(void)
{
    RblAtlas a = RblLoadAtlasFromMemory(polyFixture, (int)strlen(polyFixture), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(a), "fixture");
    if (!RblIsAtlasValid(a)) return;
    Image sheet = polySheet(), normals = polyNormalMap();
    Texture2D tex = LoadTextureFromImage(sheet), ntex = LoadTextureFromImage(normals);
    RblLight light; memset(&light, 0, sizeof(light));
    light.type = RBL_LIGHT_DIRECTIONAL; light.direction = (Vector3){ -1.0f, -0.6f, -0.8f }; light.color = WHITE; light.intensity = 1.6f;
    RT_CHECK(renderSetLights(&light, 1, (Color){ 30, 30, 40, 255 }), "scene");
    int worst[2][2] = { { 0, 0 }, { 0, 0 } }, bad = 0;
    for (int inst = 0; inst < 2; inst++)
    {
        if ((inst == 1) && !rtGlsl3()) break;
        RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
        desc.instanced = (inst == 1); desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.material.normalEncoding = RBL_NORMAL_RGB;
        Shader lit = RblLoadLitShader(desc);
        Material m = LoadMaterialDefault();
        m.shader = lit;
        m.maps[MATERIAL_MAP_ALBEDO].texture = tex;
        m.maps[MATERIAL_MAP_NORMAL].texture = ntex;
        for (int r = 0; r < 2; r++)
        {
            int draws = 0;
            PolyCount c = polyRunPath(inst? POLY_INSTANCED : POLY_BATCH, m, &a, &draws, r? 0.6f : 0.0f, r? 1 : 0);
            worst[inst][r] = c.worst;
            bad += c.badInside + c.badOutside + c.badBeyond + (c.inside < 20000);
            printf("    %s, roundness %.1f: %d inside pixels, worst %d/255 from the quad's (%d differ, the farthest %.2g texels from a texel edge), %d cut-away pixels drawn\n", inst? "instanced" : "batch", r? 0.6 : 0.0, c.inside, c.worst, c.badInside, c.edgeFar, c.badOutside);
        }
        RblUnloadLitShader(&lit);
        MemFree(m.maps);
    }
    RT_CHECK(bad == 0 && worst[0][0] == 0 && worst[1][0] == 0, "lit polygons: %d bad pixels; flat worst %d (batch) %d (instanced), rounded %d %d", bad, worst[0][0], worst[1][0], worst[0][1], worst[1][1]);
    UnloadTexture(tex); UnloadTexture(ntex); UnloadImage(sheet); UnloadImage(normals);
    RblUnloadAtlas(&a);
}
static void test_polygon_sprite_buffer_draws_the_polygon_and_none_of_the_cut_away_quad(void) { polyCheckPath(POLY_SPRITES); }

// ---- shadow casters ------------------------------------------------------------------------------
typedef struct PolyCaster { const RblAtlas *atlas; int frame, path; bool quad; } PolyCaster;

// Frame k of the fixture as a horizontal card (FIXED, facing +Z) centred at height 1, 2 world units
// per 16 frame pixels, on one path (the polygon bits cleared for the quad)
static RblBillboard polyCasterCard(const RblAtlas *a, int k, bool quad)
{
    RblBillboard b; memset(&b, 0, sizeof(b));
    RblAtlasBillboard(a, k, 2.0f/16.0f, &b);
    b.position = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.origin = (Vector2){ b.size.x*0.5f, b.size.y*0.5f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    if (quad) b.flags &= ~(unsigned int)RBL_FRAME_POLYGON;
    return b;
}

static void polyCasters(Material m, Camera3D viewer, void *ctx)
{
    const PolyCaster *c = (const PolyCaster *)ctx;
    RblBillboard b = polyCasterCard(c->atlas, c->frame, c->quad);
    if (c->path == POLY_IMMEDIATE) RblDrawBillboard(viewer, m, b);
    else if (c->path == POLY_BATCH)
    {
        RblBatch batch = RblLoadBatch(0);
        RblBeginBatch(&batch, viewer);
        RblBatchAdd(&batch, m, &b);
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
    }
    else
    {
        RblInstanceBuffer buf = RblLoadInstanceBuffer(0);
        RblInstance in = polyInstance(&b);
        RblInstancedDesc d; memset(&d, 0, sizeof(d));
        d.facing = RBL_FACING_FIXED; d.axis = b.axis; d.up = b.up;
        RT_CHECK(RblDrawInstanced(&buf, viewer, m, d, &in, 1) == 1, "instanced caster");
        RblUnloadInstanceBuffer(&buf);
    }
}

// A polygon card casts its polygon: under a light straight down, floor pixels over the polygon (by
// more than a shadow texel) are shadowed and those over the cut-away corners lit, on every caster path;
// the same card as a quad shadows the corners too
static void test_polygon_shadow_casters_cast_the_polygon_not_the_quad(void)
{
    RblAtlas a = RblLoadAtlasFromMemory(polyFixture, (int)strlen(polyFixture), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(a), "fixture");
    if (!RblIsAtlasValid(a)) return;
    ShSetup s = shSetup((Vector3){ 0.0f, 0.0f, -1.0f });
    Image sheet = polySheet();
    Texture2D tex = LoadTextureFromImage(sheet);
    ShSetup ref = s; ref.noShadow = true;
    Image lit = shRender(&ref, NULL, NULL, tex, false);
    const double margin = 2.0*SH_FOCUS/(SH_MAP - 1)/(2.0/16.0) + 0.05;      // one shadow texel, in frame pixels
    int wrong = 0, inside = 0, outside = 0, quadCorners = 0;
    for (int path = 0; path < (rtGlsl3()? 3 : 2); path++)
        for (int k = 0; k < 3; k++)
            for (int quad = 0; quad < 2; quad++)
            {
                PolyCaster c = { &a, k, path, quad == 1 };
                Image img = shRender(&s, polyCasters, &c, tex, false);
                RblBillboard b = polyCasterCard(&a, k, false);
                const RblAtlasFrame *f = &a.frames[k];
                int before = wrong;
                for (int y = 0; y < SH_TARGET; y++)
                    for (int x = 0; x < SH_TARGET; x++)
                    {
                        Vector2 p = shFloorAt(x, y);
                        double sx = (p.x + b.size.x*0.5)/b.size.x, up = (p.y + b.size.y*0.5)/b.size.y;
                        if ((sx < 0.0) || (sx > 1.0) || (up < 0.0) || (up > 1.0)) continue;
                        double fx = sx*f->trim.width, fy = (1.0 - up)*f->trim.height;
                        int base = rtPixel(lit, x, y).r, v = rtPixel(img, x, y).r;
                        bool dark = v < (base + 40)/2;
                        if (polyFixtureInside(k, fx, fy, margin)) { inside += !quad; wrong += !dark; }
                        else if (polyFixtureInside(k, fx, fy, -margin) && (fx > margin) && (fx < f->trim.width - margin) && (fy > margin) && (fy < f->trim.height - margin))
                        {
                            if (quad) quadCorners += dark;
                            else { outside++; wrong += dark; }
                        }
                    }
                if (wrong != before) { char tag[48]; snprintf(tag, sizeof(tag), "path%d-frame%d-%s", path, k, quad? "quad" : "polygon"); rtSaveImage(img, tag); }
                UnloadImage(img);
            }
    printf("    %d floor pixels under the polygons shadowed, %d under the cut-away corners lit (the quads shadow %d of them); %d wrong\n", inside, outside, quadCorners, wrong);
    RT_CHECK(wrong == 0 && inside > 2000 && outside > 1000 && quadCorners > outside/2, "%d pixels wrong (%d inside, %d cut away, %d shadowed by the quads)", wrong, inside, outside, quadCorners);
    UnloadImage(lit);
    UnloadTexture(tex); UnloadImage(sheet);
    RblUnloadAtlas(&a);
}

// ---- G-buffer -------------------------------------------------------------------------------------
// Into the G-buffer (deferred geometry variant, ambient only), resolved: inside pixels the quad's,
// cut-away pixels untouched (the clear colour)
static void test_polygon_gbuffer_holds_the_polygon_not_the_quad(void)
{
    RblAtlas a = RblLoadAtlasFromMemory(polyFixture, (int)strlen(polyFixture), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(a), "fixture");
    if (!RblIsAtlasValid(a)) return;
    Image sheet = polySheet();
    Texture2D tex = LoadTextureFromImage(sheet);
    RblGBufferDesc gd; memset(&gd, 0, sizeof(gd));
    gd.width = POLY_RT; gd.height = POLY_RT;
    RblGBuffer g = RblLoadGBuffer(gd);
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.deferred = true;
    Shader geo[2];
    geo[0] = RblLoadLitShader(desc);
    desc.instanced = true;
    geo[1] = rtGlsl3()? RblLoadLitShader(desc) : geo[0];
    RT_CHECK(RblIsGBufferValid(g) && RblIsLitShaderValid(geo[0]), "G-buffer");
    if (!RblIsGBufferValid(g)) { RblUnloadAtlas(&a); UnloadTexture(tex); UnloadImage(sheet); return; }
    RT_CHECK(renderSetLights(NULL, 0, WHITE), "scene");
    Camera3D cam = polyCamera();
    RenderTexture2D rt = LoadRenderTexture(POLY_RT, POLY_RT);
    PolyCount c; memset(&c, 0, sizeof(c));
    for (int path = 0; path < (rtGlsl3()? 3 : 2); path++)
        for (int k = 0; k < 3; k++)
        {
            Image out[2];
            RblBillboard b; memset(&b, 0, sizeof(b));
            RblAtlasBillboard(&a, k, POLY_SCALE, &b);
            b.position = (Vector3){ 3.0f, -5.0f, 0.0f };
            b.rotation = 45.0f;
            for (int quad = 0; quad < 2; quad++)
            {
                Material m = LoadMaterialDefault();
                m.shader = geo[path == POLY_INSTANCED];
                m.maps[MATERIAL_MAP_ALBEDO].texture = tex;
                RblBillboard d = b;
                if (quad) d.flags &= ~(unsigned int)RBL_FRAME_POLYGON;
                if (RblBeginGBuffer(&g, cam))
                {
                    if (path == POLY_INSTANCED)
                    {
                        RblInstanceBuffer buf = RblLoadInstanceBuffer(0);
                        RblInstance in = polyInstance(&d);
                        RT_CHECK(RblDrawInstanced(&buf, cam, m, (RblInstancedDesc){ 0 }, &in, 1) == 1, "instanced");
                        RblUnloadInstanceBuffer(&buf);
                    }
                    else if (path == POLY_IMMEDIATE) RblDrawBillboard(cam, m, d);
                    else { RblBatch batch = RblLoadBatch(0); RblBeginBatch(&batch, cam); RblBatchAdd(&batch, m, &d); RblEndBatch(&batch); RblUnloadBatch(&batch); }
                    RblEndGBuffer(&g);
                    RblDrawDeferredLights(&g);
                }
                BeginTextureMode(rt); ClearBackground(polyClear); RblResolveGBuffer(&g); EndTextureMode();
                out[quad] = rtReadTarget(rt);
                MemFree(m.maps);
            }
            polyCompare(out[1], out[0], k, &b, &a.frames[k], &c);
            if (c.badInside + c.badOutside + c.badBeyond > 0) { rtSaveImage(out[0], "gbuffer-polygon"); rtSaveImage(out[1], "gbuffer-quad"); }
            UnloadImage(out[0]); UnloadImage(out[1]);
        }
    printf("    G-buffer: %d inside pixels equal the quad's (%d differ), %d cut-away pixels the quad covered left clear (%d not)\n", c.inside - c.badInside, c.badInside, c.cutByQuad, c.badOutside);
    RT_CHECK(c.inside > 10000 && c.badInside == 0 && c.badOutside == 0 && c.badBeyond == 0 && c.cutByQuad > 10000, "G-buffer: %d inside differ, %d cut-away drawn, %d beyond", c.badInside, c.badOutside, c.badBeyond);
    UnloadRenderTexture(rt);
    RblUnloadLitShader(&geo[0]);
    if (rtGlsl3()) RblUnloadLitShader(&geo[1]);
    RblUnloadGBuffer(&g);
    UnloadTexture(tex); UnloadImage(sheet);
    RblUnloadAtlas(&a);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_POLYGON_TESTS \
    RT_TEST(test_polygon_batch_draws_the_polygon_and_none_of_the_cut_away_quad), \
    RT_TEST(test_polygon_immediate_draws_the_polygon_and_none_of_the_cut_away_quad), \
    RT_TEST_GLSL3(test_polygon_instanced_draws_the_polygon_and_none_of_the_cut_away_quad), \
    RT_TEST(test_polygon_lit_normal_mapped_pixels_equal_the_quads_flat_and_rounded), \
    RT_TEST_GLSL3(test_polygon_sprite_buffer_draws_the_polygon_and_none_of_the_cut_away_quad), \
    RT_TEST(test_polygon_shadow_casters_cast_the_polygon_not_the_quad), \
    RT_TEST_GLSL3(test_polygon_gbuffer_holds_the_polygon_not_the_quad)
