// Double-precision reference of the relief self-shadow march (RblLitShaderDesc.relief,
// shaders/relief.glsl), written from its definition, and the known height fields it is tested on
// (a step, a dome, a ridge, 32 x 32 texels). Shared by tests/test_thin.c and tests/bench/bench_thin.c.
#ifndef RBL_TEST_RELIEF_REFERENCE_H
#define RBL_TEST_RELIEF_REFERENCE_H

#include "reference.h"

#define THIN_CARD 3.0f             // world size of the tested card (square)
#define THIN_TEXELS 32
enum { THIN_STEP = 0, THIN_DOME, THIN_RIDGE, THIN_FIELDS };
static const char *const thinFieldNames[THIN_FIELDS] = { "step", "dome", "ridge" };

// 8-bit height of field f at texel (x, y) (row 0 at the top of the image)
static inline int thinHeight(int f, int x, int y)
{
    double cx = x + 0.5, cy = y + 0.5, h;
    if (f == THIN_STEP) h = (x >= 16)? 1.0 : 0.0;
    else if (f == THIN_DOME) { double r2 = ((cx - 16.0)*(cx - 16.0) + (cy - 16.0)*(cy - 16.0))/100.0; h = (r2 < 1.0)? sqrt(1.0 - r2) : 0.0; }
    else h = fmax(0.0, 1.0 - fabs(cx + 0.5*cy - 20.0)/4.0);
    return (int)floor(h*255.0 + 0.5);
}

typedef struct ThinMarch { bool lit, fragile; } ThinMarch;

// The relief march in doubles: from texel point t (texel units), heights in texels (8-bit h x depth),
// toward tangent-space direction d = (+U, +V, out of the card); `steps` evenly spaced samples up to
// the top (0 = the continuous ray: 8192 samples, under 1/100 texel apart at every reach tested). fragile: a sample within 1/500 texel of a
// texel edge or of the ray's height (float rounding may go either way there)
static inline ThinMarch thinMarch(int f, double tx, double ty, D3 d, double depth, int steps)
{
    ThinMarch m = { true, false };
    const double eps = 0.002;
    int x0 = (int)floor(tx), y0 = (int)floor(ty);
    double fx = tx - x0, fy = ty - y0;
    if ((fmin(fx, 1.0 - fx) < eps) || (fmin(fy, 1.0 - fy) < eps)) m.fragile = true;
    x0 = (x0 < 0)? 0 : ((x0 > THIN_TEXELS - 1)? THIN_TEXELS - 1 : x0);
    y0 = (y0 < 0)? 0 : ((y0 > THIN_TEXELS - 1)? THIN_TEXELS - 1 : y0);
    double base = thinHeight(f, x0, y0)/255.0*depth, rise = depth - base;
    if (!(d.z > 0.0) || !(rise > 0.0)) return m;
    double rx = d.x*rise/fmax(d.z, 0.125), ry = d.y*rise/fmax(d.z, 0.125);
    int n = (steps > 0)? steps : 8192;
    for (int i = 1; i <= n; i++)
    {
        double s = (double)i/n, px = tx + rx*s, py = ty + ry*s;
        double gx = floor(px), gy = floor(py);
        if ((steps > 0) && ((fmin(px - gx, gx + 1.0 - px) < eps) || (fmin(py - gy, gy + 1.0 - py) < eps))) m.fragile = true;
        int xi = (int)gx, yi = (int)gy;
        xi = (xi < 0)? 0 : ((xi > THIN_TEXELS - 1)? THIN_TEXELS - 1 : xi);
        yi = (yi < 0)? 0 : ((yi > THIN_TEXELS - 1)? THIN_TEXELS - 1 : yi);
        double h = thinHeight(f, xi, yi)/255.0*depth, z = base + rise*s;
        if ((steps > 0) && (fabs(h - z) < eps)) m.fragile = true;
        if (h > z) { m.lit = false; break; }
    }
    return m;
}

#if defined(RAYLIB_H)
// Field f's heights in the alpha of a THIN_TEXELS square texture (RGB 0), as a relief material holds them
static inline Texture2D thinHeightTexture(int f)
{
    Image heights = GenImageColor(THIN_TEXELS, THIN_TEXELS, BLANK);
    for (int y = 0; y < THIN_TEXELS; y++)
        for (int x = 0; x < THIN_TEXELS; x++) ImageDrawPixel(&heights, x, y, (Color){ 0, 0, 0, (unsigned char)thinHeight(f, x, y) });
    Texture2D t = LoadTextureFromImage(heights);
    UnloadImage(heights);
    return t;
}
#endif

#endif
