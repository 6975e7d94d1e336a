// Benchmark support: a monotonic clock, the median of repeated timed runs (warm-up, run count and
// time budget bounded) and CSV rows "suite,case,metric,value,unit" appended to $BENCH_CSV
// (default build/bench/results.csv; tests/bench/run.sh creates it fresh with the header line).
#ifndef RBL_BENCH_H
#define RBL_BENCH_H

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define BENCH_CSV_HEADER    "suite,case,metric,value,unit"
#define BENCH_MAX_RUNS      64      // Runs a median is taken over, at most
#define BENCH_MAX_VALUES    64      // Values one run may report

// ---- clock ----------------------------------------------------------------------------------
// Monotonic time in nanoseconds (origin unspecified: use differences only)
static inline double BenchNowNs(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec*1e9 + (double)ts.tv_nsec;
}

// ---- median of N ----------------------------------------------------------------------------
// Median of count values; the array is sorted in place (insertion sort: count is small)
static inline double BenchMedian(double *values, int count)
{
    if (count <= 0) return 0.0;
    for (int i = 1; i < count; i++)
    {
        double v = values[i];
        int j = i - 1;
        while ((j >= 0) && (values[j] > v)) { values[j + 1] = values[j]; j--; }
        values[j + 1] = v;
    }
    return (count%2 == 1)? values[count/2] : 0.5*(values[count/2 - 1] + values[count/2]);
}

// One timed run: writes its valueCount measurements (e.g. total, submit, flush) to out
typedef void (*BenchRunFn)(void *ctx, double *out);

typedef struct BenchTiming {
    int warmup;             // Untimed runs first
    int minRuns;            // Timed runs at least (even past the budget)
    int maxRuns;            // Timed runs at most (<= BENCH_MAX_RUNS)
    double budgetNs;        // Wall time after which no further run starts once minRuns are done
} BenchTiming;

// Runs fn timing.warmup times, then timed runs until maxRuns or (past minRuns) the budget is
// spent; medians[k] = median of the k-th value over the timed runs. Returns the timed run count.
static inline int BenchMedianOfRuns(BenchRunFn fn, void *ctx, int valueCount, BenchTiming timing, double *medians)
{
    double samples[BENCH_MAX_VALUES][BENCH_MAX_RUNS];
    double out[BENCH_MAX_VALUES];
    if (valueCount > BENCH_MAX_VALUES) valueCount = BENCH_MAX_VALUES;
    if (timing.maxRuns > BENCH_MAX_RUNS) timing.maxRuns = BENCH_MAX_RUNS;
    if (timing.minRuns < 1) timing.minRuns = 1;
    if (timing.maxRuns < timing.minRuns) timing.maxRuns = timing.minRuns;

    for (int i = 0; i < timing.warmup; i++) fn(ctx, out);

    double start = BenchNowNs();
    int runs = 0;
    while (runs < timing.maxRuns)
    {
        if ((runs >= timing.minRuns) && (BenchNowNs() - start > timing.budgetNs)) break;
        fn(ctx, out);
        for (int k = 0; k < valueCount; k++) samples[k][runs] = out[k];
        runs++;
    }
    for (int k = 0; k < valueCount; k++) medians[k] = BenchMedian(samples[k], runs);
    return runs;
}

// A frame timer: frame(ctx, i) draws and times case i (i < 0: the baseline frame), in ms
typedef double (*BenchFrameFn)(void *ctx, int i);

// One paired round: each case with ok[i] set timed once, right after a baseline frame. out[i] = ms,
// out[cases + i] = ratio to the round's baseline (the median of its baseline frames, or one baseline
// frame when no case runs); returns that baseline
static inline double BenchPairedRound(BenchFrameFn frame, void *ctx, const bool *ok, int cases, double *out)
{
    double base[BENCH_MAX_VALUES];
    int nb = 0;
    for (int i = 0; (i < cases) && (i < BENCH_MAX_VALUES); i++)
    {
        out[i] = 0.0;
        if (!ok[i]) continue;
        base[nb++] = frame(ctx, -1);
        out[i] = frame(ctx, i);
    }
    double roundBase = (nb > 0)? BenchMedian(base, nb) : frame(ctx, -1);
    for (int i = 0; i < cases; i++) out[cases + i] = (roundBase > 0.0)? out[i]/roundBase : 0.0;
    return roundBase;
}

// ---- CSV ------------------------------------------------------------------------------------
static inline const char *BenchCsvPath(void)
{
    const char *path = getenv("BENCH_CSV");
    return ((path != NULL) && (path[0] != '\0'))? path : "build/bench/results.csv";
}

// Appends one row; a missing or empty file gets the header line first. Names must not hold commas.
static inline bool BenchCsvRow(const char *suite, const char *name, const char *metric, double value, const char *unit)
{
    static bool warned = false;
    FILE *file = fopen(BenchCsvPath(), "a");
    if (file == NULL)
    {
        if (!warned) fprintf(stderr, "bench: cannot append to %s\n", BenchCsvPath());
        warned = true;
        return false;
    }
    fseek(file, 0, SEEK_END);
    if (ftell(file) == 0) fprintf(file, "%s\n", BENCH_CSV_HEADER);
    fprintf(file, "%s,%s,%s,%.6g,%s\n", suite, name, metric, value, unit);
    fclose(file);
    return true;
}

#endif // RBL_BENCH_H
