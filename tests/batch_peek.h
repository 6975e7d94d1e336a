// Reading a batch's CPU data in tests and benches (the implementation included first): slot i's
// four vertices, from the vertex stream or, where the batch holds the compact stream, its record
// (the billboard) expanded by the vertex path (rbl__recordVertices, in the pass the batch began in).
// Records the adds wrote into the mapped GPU buffer are read back first (rbl__recordsToCpu: a batch
// in progress then keeps the rest on the CPU)
#ifndef RBL_BATCH_PEEK_H
#define RBL_BATCH_PEEK_H

static inline void rtBatchVertices(rbl__BatchState *st, int i, RblVertex out[4])
{
    if (!st->records) { memcpy(out, st->vertices + (size_t)i*4, 4*sizeof(RblVertex)); return; }
    if (st->onGpu && !rbl__recordsToCpu(st)) { memset(out, 0, 4*sizeof(RblVertex)); return; }
    int r = 0;
    while ((r + 1 < st->runCount) && (st->runs[r + 1].first <= i)) r++;
    rbl__FrameCache cache;
    cache.facing = -1;
    rbl__recordVertices(st, r, i, &cache, out);
}

#endif
