// libFuzzer target for the atlas readers, one binary per format (FUZZ_FORMAT: RBL_ATLAS_TEXTUREPACKER,
// _ASEPRITE, _LIBGDX; each also auto-detects every other input). Built with
// clang -fsanitize=fuzzer,address,undefined; `make test` runs each for a bounded time over
// tests/fuzz/corpus/<format>/ (hand-written seeds). Beyond the sanitizers, it aborts when a refused
// input does not log exactly one line, or an accepted one yields a frame table whose frames, tags or
// billboard fields break the documented invariants (pages, polygons and what a batch draws of them,
// 9-slice centres, slice keys and their sub-frames among them), or the player leaves its tag. LOG_INFO lines (what an accepted atlas
// leaves unread) are at most one per load, and never on a refusal.
// Built in two parts so the header's implementation is instrumented once for the three targets:
// -DFUZZ_IMPL compiles only the implementation; the targets include the declarations.
#if defined(FUZZ_IMPL)
    #define RBILLBOARD_LIT_IMPLEMENTATION
    #include "rbillboard_lit.h"
#else
#include "rbillboard_lit.h"
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef FUZZ_FORMAT
    #define FUZZ_FORMAT RBL_ATLAS_AUTO
#endif

static int lines = 0, infoLines = 0;
static void countLog(int level, const char *text, va_list args)
{
    (void)args;
    if (strncmp(text, "RBL:", 4) != 0) return;
    if (level >= LOG_WARNING) lines++; else infoLines++;
}

static void expect(bool ok, const char *what)
{
    if (ok) return;
    fprintf(stderr, "fuzz_atlas: invariant broken: %s\n", what);
    abort();
}

static bool finiteRect(Rectangle r) { return isfinite(r.x) && isfinite(r.y) && isfinite(r.width) && isfinite(r.height); }
static bool inside(Vector2 p, float x, float y, float w, float h) { return (p.x >= x) && (p.y >= y) && (p.x <= x + w) && (p.y <= y + h); }

static void check(const RblAtlas *a)
{
    expect(a->frameCount > 0 && a->pageCount > 0, "empty table accepted");
    for (int p = 0; p < a->pageCount; p++)
    {
        const RblAtlasPage *g = &a->pages[p];
        expect(g->image != NULL && g->width >= 0 && g->height >= 0 && (g->width > 0) == (g->height > 0), "page image/size");
        expect(isfinite(g->scale) && g->scale >= 1.0f/65536.0f && g->scale <= 65536.0f, "page scale");
    }
    for (int i = 0; i < a->frameCount; i++)
    {
        const RblAtlasFrame *f = &a->frames[i];
        expect(f->name != NULL && f->page >= 0 && f->page < a->pageCount, "frame name/page");
        expect(finiteRect(f->block) && f->block.width > 0 && f->block.height > 0 && f->block.x >= 0 && f->block.y >= 0, "frame block");
        const RblAtlasPage *p = &a->pages[f->page];
        if (p->width > 0) expect(f->block.x + f->block.width <= p->width && f->block.y + f->block.height <= p->height, "block outside the stated sheet");
        expect(f->trim.x >= 0 && f->trim.y >= 0 && f->trim.x + f->trim.width <= f->size.x && f->trim.y + f->trim.height <= f->size.y, "trim outside the frame");
        expect(isfinite(f->pivot.x) && isfinite(f->pivot.y) && f->duration >= 0 && isfinite(f->duration), "pivot/duration");
        RblBillboard b; memset(&b, 0, sizeof(b));
        expect(RblAtlasBillboard(a, i, 0.01f, &b), "billboard refused");
        expect(finiteRect(b.source) && isfinite(b.size.x) && isfinite(b.size.y) && isfinite(b.origin.x) && isfinite(b.origin.y) && b.size.x > 0 && b.size.y > 0, "billboard fields");
        expect(strlen(f->name) < (1u << 20), "name");   // a C string inside the text's bound
        const Rectangle c = f->center;
        expect(finiteRect(c) && c.x >= 0 && c.y >= 0 && c.width >= 0 && c.height >= 0 && c.x + c.width <= f->size.x && c.y + c.height <= f->size.y, "9-slice centre outside the frame");
        const RblAtlasPolygon *poly = f->polygon;
        if (poly != NULL)
        {
            expect(poly->vertexCount >= 3 && poly->vertexCount <= 65535 && poly->indexCount >= 3 && poly->indexCount%3 == 0, "polygon counts");
            for (int v = 0; v < poly->vertexCount; v++)
                expect(inside(poly->vertices[v], 0, 0, f->size.x, f->size.y) && inside(poly->uvs[v], f->block.x, f->block.y, f->block.width, f->block.height), "polygon point outside its frame");
            for (int k = 0; k < poly->indexCount; k++) expect(poly->indices[k] < poly->vertexCount, "polygon index");
        }
        // What a batch draws of it: the polygon's quads (its RBL_FRAME_POLYGON bits name it) or the one
        // quad, flat, rounded and mirrored; every vertex finite, its texel inside the frame's block
        expect(((b.flags & RBL_FRAME_POLYGON) != 0) == (poly != NULL), "polygon bits");
        for (int variant = 0; variant < 3; variant++)
        {
            RblBillboard d = b;
            if (variant > 0) d.roundness = 0.5f;
            if (variant == 2) { d.size.x = -d.size.x; d.rotation = 33.0f; }
            static const RblCameraFrame view = { { 0.0f, 0.0f, 5.0f }, { 1.0f, 0.0f, 0.0f }, { 0.0f, 1.0f, 0.0f }, { 0.0f, 0.0f, 1.0f }, false };
            int w = (p->width > 0)? p->width : 65536, h = (p->height > 0)? p->height : 65536, before = lines;
            int n = RblBillboardQuads(&view, w, h, &d, NULL, 0);
            expect((lines == before) && (n >= 0) && ((poly != NULL) || (n == 1)) && ((poly == NULL) || (n <= poly->indexCount*3)), "quad count");
            RblVertex *v = (RblVertex *)malloc((size_t)(n > 0? n : 1)*4*sizeof(RblVertex));
            expect(v != NULL && RblBillboardQuads(&view, w, h, &d, v, n) == n, "quads emitted");
            for (int q = 0; q < 4*n; q++)
            {
                bool finite = true;
                for (int e = 0; e < 3; e++) finite = finite && isfinite(v[q].position[e]) && isfinite(v[q].normal[e]) && isfinite(v[q].tangent[e]);
                float tu = v[q].texcoord[0]*(float)w, tv = v[q].texcoord[1]*(float)h, tol = 1e-3f*(1.0f + f->block.x + f->block.width + f->block.y + f->block.height);
                expect(finite && (tu >= f->block.x - tol) && (tu <= f->block.x + f->block.width + tol) && (tv >= f->block.y - tol) && (tv <= f->block.y + f->block.height + tol), "quad vertex outside its frame or not finite");
            }
            free(v);
        }
    }
    for (int t = 0; t < a->tagCount; t++)
    {
        const RblAtlasTag *g = &a->tags[t];
        expect(g->name != NULL && g->from >= 0 && g->from <= g->to && g->to < a->frameCount && g->direction >= 0 && g->direction <= 3 && g->repeat >= 0, "tag range");
        RblSpritePlayer p = RblPlaySprite(a, t, 0);
        for (int k = 0; k < 8; k++)
        {
            expect(RblUpdateSprite(&p, a, (k == 5)? 1e6f : 0.037f*(float)k), "update refused");
            expect(p.frame >= g->from && p.frame <= g->to && p.time >= 0 && isfinite(p.time), "player left its tag");
            int next = -1;
            float w = RblSpriteBlend(&p, a, &next);
            expect(w >= 0 && w <= 1 && next >= g->from && next <= g->to, "blend");
        }
    }
    for (int s = 0; s < a->sliceCount; s++)
    {
        const RblAtlasSlice *k = &a->slices[s];
        expect(k->name != NULL && finiteRect(k->bounds) && k->bounds.width > 0 && k->bounds.height > 0 && finiteRect(k->center) && isfinite(k->pivot.x) && isfinite(k->pivot.y), "slice");
        expect(k->frame >= 0 && k->frame <= k->lastFrame && k->lastFrame < a->frameCount, "slice key frames");
        int found = RblAtlasFindSlice(a, k->name, k->frame);
        expect(found >= 0 && found <= s && a->slices[found].frame <= k->frame && k->frame <= a->slices[found].lastFrame, "slice lookup");
        // its sub-frame: drawn (finite, positive) or refused with one line (outside the drawn pixels)
        RblBillboard b; memset(&b, 0, sizeof(b));
        int before = lines;
        bool ok = RblAtlasSliceBillboard(a, s, k->lastFrame, 0.01f, &b);
        expect(ok? (lines == before && finiteRect(b.source) && b.size.x > 0 && b.size.y > 0 && isfinite(b.origin.x) && isfinite(b.origin.y)) : (lines == before + 1), "slice sub-frame");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static bool init = false;
    if (!init) { SetTraceLogLevel(LOG_INFO); SetTraceLogCallback(countLog); init = true; }
    if (size == 0 || size > (1u << 20)) return 0;
    for (int pass = 0; pass < 2; pass++)
    {
        lines = 0; infoLines = 0;
        RblAtlas a = RblLoadAtlasFromMemory((const char *)data, (int)size, (pass == 0)? FUZZ_FORMAT : RBL_ATLAS_AUTO);
        if (RblIsAtlasValid(a))
        {
            expect(lines == 0 && infoLines <= 1, "accepted with warning lines, or more than one INFO line");
            lines = 0;
            check(&a);
            RblUnloadAtlas(&a);
            expect(!RblIsAtlasValid(a), "unload");
        }
        else expect(lines == 1 && infoLines == 0 && a.state == NULL && a.frames == NULL, "refused without exactly one line");
    }
    return 0;
}
#endif // FUZZ_IMPL
