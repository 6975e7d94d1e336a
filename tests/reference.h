// Double-precision reference for billboard geometry, written independently of the header:
// camera-plane follows raylib's DrawBillboardPro literally, the other modes their definitions.
#ifndef RBL_TEST_REFERENCE_H
#define RBL_TEST_REFERENCE_H

typedef struct { double x, y, z; } D3;
static inline D3 d3(double x, double y, double z) { D3 r = { x, y, z }; return r; }
static inline D3 d3f(Vector3 v) { return d3(v.x, v.y, v.z); }
static inline D3 dAdd(D3 a, D3 b) { return d3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline D3 dSub(D3 a, D3 b) { return d3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline D3 dScale(D3 a, double s) { return d3(a.x*s, a.y*s, a.z*s); }
static inline double dDot(D3 a, D3 b) { return a.x*b.x + a.y*b.y + a.z*b.z; }
static inline D3 dCross(D3 a, D3 b) { return d3(a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x); }
static inline double dLen(D3 a) { return sqrt(dDot(a, a)); }
static inline D3 dNorm(D3 a) { return dScale(a, 1.0/dLen(a)); }
// Rodrigues rotation of v about unit k by angle a (radians)
static inline D3 dRotate(D3 v, D3 k, double a)
{
    double c = cos(a), s = sin(a);
    return dAdd(dAdd(dScale(v, c), dScale(dCross(k, v), s)), dScale(k, dDot(k, v)*(1.0 - c)));
}

// Corners in the header's order (bottom-left, bottom-right, top-right, top-left) and the unit normal.
// Camera-plane follows raylib's DrawBillboardPro literally (scaled vectors, origin from the
// normalised ones, rotation about cross(right, up)); the other modes follow their definitions.
static inline void refQuad(Camera3D cam, const RblBillboard *b, D3 out[4], D3 *normal)
{
    D3 eye = d3f(cam.position), back = dNorm(dSub(eye, d3f(cam.target)));
    D3 right = dNorm(dCross(d3f(cam.up), back)), vup = dCross(back, right);
    D3 pos = d3f(b->position), R, U, N;
    double sx = fabs(b->size.x), sy = fabs(b->size.y);
    if (b->facing == RBL_FACING_CAMERA_PLANE)
    {
        R = right;
        U = (dLen(d3f(b->up)) > 0.0)? d3f(b->up) : vup;
        N = dNorm(dCross(R, U));
    }
    else if (b->facing == RBL_FACING_CAMERA_POSITION)
    {
        N = dNorm(dSub(eye, pos));
        R = dNorm(dCross(vup, N));
        U = dCross(N, R);
    }
    else if (b->facing == RBL_FACING_AXIS)
    {
        D3 a = (dLen(d3f(b->axis)) > 0.0)? dNorm(d3f(b->axis)) : d3(0, 1, 0);
        D3 d = dSub(eye, pos);
        N = dNorm(dSub(d, dScale(a, dDot(d, a))));
        U = a;
        R = dCross(U, N);
    }
    else
    {
        N = (dLen(d3f(b->axis)) > 0.0)? dNorm(d3f(b->axis)) : d3(0, 0, 1);
        D3 up = (dLen(d3f(b->up)) > 0.0)? d3f(b->up) : d3(0, 1, 0);
        U = dNorm(dSub(up, dScale(N, dDot(up, N))));
        R = dCross(U, N);
    }
    D3 rs = dScale(R, sx), us = dScale(U, sy);
    D3 origin3D = dAdd(dScale(dNorm(R), b->origin.x), dScale(dNorm(U), b->origin.y));
    D3 pts[4] = { d3(0, 0, 0), rs, dAdd(rs, us), us };
    for (int i = 0; i < 4; i++)
    {
        D3 p = dSub(pts[i], origin3D);
        if (b->rotation != 0.0f) p = dRotate(p, N, b->rotation*PI/180.0);
        out[i] = dAdd(p, pos);
    }
    *normal = N;
}

static inline Camera3D makeCamera(Vector3 pos, Vector3 target, Vector3 up)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = pos; c.target = target; c.up = up; c.fovy = 45.0f; c.projection = CAMERA_PERSPECTIVE;
    return c;
}

static inline double v3dist(const float *p, D3 r) { return dLen(dSub(d3(p[0], p[1], p[2]), r)); }
static inline D3 vecOf(const float *p) { return d3(p[0], p[1], p[2]); }

// Exact sRGB transfer functions (IEC 61966-2-1), for references of the lit output
static inline double srgbDecode(double c) { return (c <= 0.04045)? c/12.92 : pow((c + 0.055)/1.055, 2.4); }
static inline double srgbEncode(double l) { l = fmin(fmax(l, 0.0), 1.0); return (l <= 0.0031308)? l*12.92 : 1.055*pow(l, 1.0/2.4) - 0.055; }

#endif
