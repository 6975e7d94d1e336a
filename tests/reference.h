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

// Near-degenerate blend as documented (README "Facing modes"): a frame direction taken from v off the
// axis n becomes unit(w unit(v off n) + (1 - w) unit(f off n)) with w = smoothstep(lo, hi, sine(v, n)),
// f the fallback; billboards blend over sines 1/64..1/8, the camera frame over 1e-6..1e-5. A v shorter
// than 1e-12 counts as along n. Written from the documentation, in double.
#define REF_BLEND_LO (1.0/64.0)
#define REF_BLEND_HI (1.0/8.0)
#define REF_CAMERA_BLEND_LO 1e-6
#define REF_CAMERA_BLEND_HI 1e-5
static inline double refSmoothstep(double lo, double hi, double x)
{
    double t = fmin(fmax((x - lo)/(hi - lo), 0.0), 1.0);
    return t*t*(3.0 - 2.0*t);
}
static inline D3 refOff(D3 v, D3 n) { return dSub(v, dScale(n, dDot(v, n))); }
static inline double refSine(D3 v, D3 n) { return (dDot(v, v) > 1e-24)? dLen(refOff(v, n))/dLen(v) : 0.0; }
static inline D3 refBlendDir(D3 v, D3 f, D3 n, double lo, double hi)
{
    double w = refSmoothstep(lo, hi, refSine(v, n));
    D3 c = dScale(dNorm(refOff(f, n)), 1.0 - w);
    if (w > 0.0) c = dAdd(c, dScale(dNorm(refOff(v, n)), w));
    return dNorm(refOff(c, n));
}
// Fallback up for a vector d along which up cannot be taken: -Z / +Z for d along +Y / -Y, else +Y
// (by d's largest component)
static inline D3 refFallbackUp(D3 d)
{
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z);
    return ((ay >= ax) && (ay >= az))? d3(0, 0, (d.y > 0.0)? -1.0 : 1.0) : d3(0, 1, 0);
}

// The camera frame: back from target to eye (+Z if they coincide), up = camera.up off back blended
// toward the fallback up, right = up x back
static inline void refCameraFrame(Camera3D cam, D3 *right, D3 *up, D3 *back)
{
    D3 d = dSub(d3f(cam.position), d3f(cam.target));
    *back = (dDot(d, d) > 1e-24)? dNorm(d) : d3(0, 0, 1);
    D3 u = refBlendDir(d3f(cam.up), refFallbackUp(*back), *back, REF_CAMERA_BLEND_LO, REF_CAMERA_BLEND_HI);
    *right = dCross(u, *back);
    *up = dCross(*back, *right);
}

// Facing frame: right R, up U (CAMERA_PLANE with a caller up: that up's length and its part along R
// kept, its part off R turned to the blended direction; else unit), unit normal N. A shadow pass
// (minSin > 0) tilts AXIS billboards about R until the light l sees them at asin(minSin): the tilt
// angle from atan2/acos here (the header avoids inverse trig), faded toward none as the sine between
// l and R drops through the blend band.
static inline void refFrame(Camera3D cam, const RblBillboard *b, Vector4 light, double minSin, D3 *R, D3 *U, D3 *N)
{
    D3 right, vup, back;
    refCameraFrame(cam, &right, &vup, &back);
    D3 eye = d3f(cam.position), pos = d3f(b->position);
    D3 toEye = (cam.projection == CAMERA_ORTHOGRAPHIC)? back : dSub(eye, pos);      // a parallel view's eye is at infinity along back
    *R = right; *U = vup; *N = back;
    if (b->facing == RBL_FACING_CAMERA_PLANE)
    {
        D3 up = d3f(b->up);
        if (dDot(up, up) > 1e-24)
        {
            D3 ud = refBlendDir(up, vup, right, REF_BLEND_LO, REF_BLEND_HI);
            *N = dCross(right, ud);
            *U = dAdd(dScale(right, dDot(up, right)), dScale(ud, dLen(refOff(up, right))));
        }
    }
    else if (b->facing == RBL_FACING_CAMERA_POSITION)
    {
        D3 d = toEye;
        if (dDot(d, d) > 1e-24)
        {
            *N = dNorm(d);
            *U = refBlendDir(vup, dCross(*N, right), *N, REF_BLEND_LO, REF_BLEND_HI);
            *R = dCross(*U, *N);
        }
    }
    else if (b->facing == RBL_FACING_AXIS)
    {
        D3 a = (dDot(d3f(b->axis), d3f(b->axis)) > 1e-24)? dNorm(d3f(b->axis)) : d3(0, 1, 0);
        D3 f = refBlendDir(back, vup, a, REF_BLEND_LO, REF_BLEND_HI);
        D3 n = refBlendDir(toEye, f, a, REF_BLEND_LO, REF_BLEND_HI);
        *U = a; *N = n; *R = dCross(a, n);
        if (minSin > 0.0)
        {
            D3 l = dNorm(dSub(d3(light.x, light.y, light.z), dScale(pos, light.w)));
            double ln = dDot(l, n), la = dDot(l, a), x = fabs(ln), y = fabs(la), rho = hypot(x, y);
            if ((x < minSin) && (rho > 0.0))
            {
                // l's direction in the (n, a) plane is at angle phi from n; the quad's normal tilted by t
                // toward it sees l at sine rho cos(phi - t) = minSin, or faces it (t = phi) if it cannot
                double phi = atan2(y, x), t = (rho > minSin)? phi - acos(minSin/rho) : phi;
                double w = refSmoothstep(REF_BLEND_LO, REF_BLEND_HI, rho);
                double c = w*cos(t) + (1.0 - w), sn = w*sin(t), h = hypot(c, sn);
                c /= h; sn /= h;
                if ((ln >= 0.0) != (la >= 0.0)) sn = -sn;
                *N = dAdd(dScale(n, c), dScale(a, sn));
                *U = dSub(dScale(a, c), dScale(n, sn));
            }
        }
    }
    else
    {
        D3 n = (dDot(d3f(b->axis), d3f(b->axis)) > 1e-24)? dNorm(d3f(b->axis)) : d3(0, 0, 1);
        D3 up = (dDot(d3f(b->up), d3f(b->up)) > 1e-24)? d3f(b->up) : d3(0, 1, 0);
        *N = n;
        *U = refBlendDir(up, refFallbackUp(n), n, REF_BLEND_LO, REF_BLEND_HI);
        *R = dCross(*U, n);
    }
}

// Corners in the header's order (bottom-left, bottom-right, top-right, top-left) and the unit normal,
// from refFrame. Camera-plane follows raylib's DrawBillboardPro literally (scaled vectors, origin from
// the normalised ones, rotation about cross(right, up)); the other modes follow their definitions.
static inline void refQuadCast(Camera3D cam, const RblBillboard *b, Vector4 light, double minSin, D3 out[4], D3 *normal)
{
    D3 R, U, N;
    refFrame(cam, b, light, minSin, &R, &U, &N);
    D3 pos = d3f(b->position);
    double sx = fabs(b->size.x), sy = fabs(b->size.y);
    D3 rs = dScale(R, sx), us = dScale(U, sy);
    D3 origin3D = dAdd(dScale(dNorm(R), b->origin.x), dScale(dNorm(U), b->origin.y));
    D3 pts[4] = { d3(0, 0, 0), rs, dAdd(rs, us), us };
    for (int i = 0; i < 4; i++)
    {
        D3 p = dSub(pts[i], origin3D);
        if (b->rotation != 0.0f) p = dRotate(p, N, fmod((double)b->rotation, 360.0)*PI/180.0);
        out[i] = dAdd(p, pos);
    }
    *normal = N;
}

static inline void refQuad(Camera3D cam, const RblBillboard *b, D3 out[4], D3 *normal)
{
    Vector4 none = { 0.0f, 0.0f, 0.0f, 0.0f };
    refQuadCast(cam, b, none, 0.0, out, normal);
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
