// Reading a batch's CPU data in tests and benches (the implementation included first): slot i's
// four vertices, from the vertex stream or, where the batch holds the compact stream, its record
// expanded by the CPU mirror of the vertex stage (rbl__recordVertices)
#ifndef RBL_BATCH_PEEK_H
#define RBL_BATCH_PEEK_H

static inline void rtBatchVertices(const rbl__BatchState *st, int i, RblVertex out[4])
{
    if (st->records) rbl__recordVertices((const rbl__BatchRecord *)(const void *)st->vertices + i, out);
    else memcpy(out, st->vertices + (size_t)i*4, 4*sizeof(RblVertex));
}

#endif
