// Near-degenerate billboard frames: every configuration in which the header's facing code falls
// back (README "Degenerate frames"), approached rather than reached. Angular cases sweep the
// approach angle log-spaced from 5 degrees down to 1e-7 rad, from both sides of the degenerate
// direction and at six azimuths 60 degrees apart starting at the fallback's own direction (so the
// sweep passes straight through the blend's aligned and opposed sides). Offset cases (a point
// reaching the eye) sweep the offset's length. Shared by the CPU suite (frames against the double
// reference) and the GPU suite (instanced stage against the CPU path); builds the configurations in
// double and rounds them to the float inputs the header gets (the references take those as exact).
#ifndef RBL_TEST_DEGENERATE_H
#define RBL_TEST_DEGENERATE_H

#include "reference.h"

enum {
    DG_CAMERA_UP,       // camera.up nearly along the view (+Y, and a tilted up), looking down and up
    DG_PLANE_UP,        // CAMERA_PLANE: the caller's up nearly along the camera's right
    DG_POSITION_UP,     // CAMERA_POSITION: the centre nearly on the camera's screen-up line (shadow passes)
    DG_AXIS_EYE,        // AXIS: the eye nearly on the locked axis (+Y, and a tilted axis)
    DG_AXIS_VIEW,       // AXIS: the eye on the axis and the view nearly along it (the second fallback)
    DG_FIXED_UP,        // FIXED: up nearly along the normal
    DG_FIXED_NORMAL,    // FIXED: the default up (+Y) with the normal nearly +-Y (a decal on near-level ground)
    DG_TILT_LIGHT,      // AXIS in a shadow pass: the light nearly along the pivot line (no tilt can help)
    DG_CAMERA_TARGET,   // offset: camera.target reaching camera.position
    DG_POSITION_EYE,    // offset: a CAMERA_POSITION centre reaching the eye
    DG_CONFIGS
};

static const char *const dgNames[DG_CONFIGS] = {
    "camera up ~ view", "plane up ~ right", "position ~ screen-up line", "axis: eye ~ axis", "axis: view ~ axis (eye on it)",
    "fixed: up ~ normal", "fixed: normal ~ default up", "shadow tilt: light ~ pivot line", "camera target -> position", "position -> eye"
};

#define DG_ANGLES 37            // 5 degrees .. 1e-7 rad, about 6 per decade
#define DG_AZIMUTHS 6
#define DG_VARIANTS 4           // side (+-) x two variants (default / tilted axis, or two lengths)
#define DG_CASES (DG_ANGLES*DG_AZIMUTHS*DG_VARIANTS)

static inline bool dgIsOffset(int config) { return (config == DG_CAMERA_TARGET) || (config == DG_POSITION_EYE); }

// Approach angle i (radians; 0 = 5 degrees), or for offset cases the offset's length (1 .. 1e-13)
static inline double dgAngle(int config, int i)
{
    double t = (double)i/(DG_ANGLES - 1);
    if (dgIsOffset(config)) return pow(10.0, -13.0*t);
    return exp(log(5.0*PI/180.0)*(1.0 - t) + log(1e-7)*t);
}

typedef struct {
    Camera3D camera;
    RblBillboard billboard;     // one billboard (facing, up, axis, position, size, origin)
    Vector4 light;              // shadow pass light (DG_TILT_LIGHT), else zero
    float minSin;               // shadow pass minimum sine (DG_TILT_LIGHT), else 0
    double angle;               // approach angle (rad) or offset length
    int side, variant, azimuth;
} DgCase;

static inline Vector3 dgF(D3 v) { return (Vector3){ (float)v.x, (float)v.y, (float)v.z }; }

// cos(angle) axis + sin(angle) (cos(az) e1 + sin(az) e2), e1 = the component of ref off unit axis
static inline D3 dgTilt(D3 axis, D3 ref, double angle, double azimuth)
{
    D3 e1 = dNorm(dSub(ref, dScale(axis, dDot(ref, axis)))), e2 = dCross(axis, e1);
    D3 off = dAdd(dScale(e1, cos(azimuth)), dScale(e2, sin(azimuth)));
    return dAdd(dScale(axis, cos(angle)), dScale(off, sin(angle)));
}

// The double frame of a well-conditioned camera (the sweeps' fixed viewers)
static inline void dgViewOf(Camera3D c, D3 *right, D3 *up, D3 *back)
{
    *back = dNorm(dSub(d3f(c.position), d3f(c.target)));
    *right = dNorm(dCross(d3f(c.up), *back));
    *up = dCross(*back, *right);
}

// A configuration approached at angle (or offset length) from side +-1, variant 0/1, azimuth
// 0..5 (x 60 degrees)
static inline DgCase dgCaseAt(int config, int side, int variant, int azimuth, double angle)
{
    DgCase c;
    memset(&c, 0, sizeof(c));
    c.azimuth = azimuth; c.variant = variant; c.side = side; c.angle = angle;
    double az = c.azimuth*(PI/3.0), sd = c.side;
    RblBillboard *b = &c.billboard;
    b->size = (Vector2){ 1.5f, 2.0f }; b->origin = (Vector2){ 0.75f, 0.5f };
    b->position = (Vector3){ 1.0f, 0.5f, -2.0f };
    // A well-conditioned viewer for the cases that do not degenerate the camera itself
    c.camera = makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.1f, 1.0f, 0.0f });
    D3 R, U, B;
    dgViewOf(c.camera, &R, &U, &B);
    const D3 Y = d3(0, 1, 0), tilted = dNorm(d3(0.3, 1.0, -0.2));
    switch (config)
    {
        case DG_CAMERA_UP:
        {
            // up +Y or tilted; the view comes within the angle of it (back ~ side*up), fallback -Z / +Z or +Y
            D3 up = c.variant? tilted : Y, target = d3(1.0, 2.0, -3.0);
            D3 back = dgTilt(dScale(up, sd), d3(0, 0, -sd), c.angle, az);
            c.camera = makeCamera(dgF(dAdd(target, dScale(back, 10.0))), dgF(target), dgF(up));
            b->facing = RBL_FACING_CAMERA_PLANE;
            b->position = dgF(dSub(target, dScale(back, 2.0)));
        } break;
        case DG_PLANE_UP:
        {
            // caller up (length 1 or 2.5) within the angle of +-right; the fallback up is the camera's
            double len = c.variant? 2.5 : 1.0;
            b->facing = RBL_FACING_CAMERA_PLANE;
            b->up = dgF(dScale(dgTilt(dScale(R, sd), U, c.angle, az), len));
        } break;
        case DG_POSITION_UP:
        {
            // centre 7 (or 0.5) units from the eye, within the angle of the camera's up line
            double dist = c.variant? 0.5 : 7.0;
            b->facing = RBL_FACING_CAMERA_POSITION;
            b->position = dgF(dSub(d3f(c.camera.position), dScale(dgTilt(dScale(U, sd), dScale(B, -sd), c.angle, az), dist)));
        } break;
        case DG_AXIS_EYE:
        {
            // eye within the angle of the axis (+Y by default, or tilted), 6 units away along it
            D3 a = c.variant? tilted : Y;
            b->facing = RBL_FACING_AXIS;
            if (c.variant) b->axis = dgF(dScale(a, 2.0));
            b->position = dgF(dSub(d3f(c.camera.position), dScale(dgTilt(dScale(a, sd), B, c.angle, az), 6.0)));
        } break;
        case DG_AXIS_VIEW:
        {
            // eye on the axis (4 units above or below the centre), looking within the angle of the axis
            D3 a = c.variant? tilted : Y, eye = d3(1.0, 8.0, 2.0);
            D3 camUp = dNorm(d3(0.2, 0.3, -1.0));
            D3 back = dgTilt(dScale(a, sd), camUp, c.angle, az);
            c.camera = makeCamera(dgF(eye), dgF(dSub(eye, dScale(back, 10.0))), dgF(camUp));
            b->facing = RBL_FACING_AXIS;
            if (c.variant) b->axis = dgF(a);
            b->position = dgF(dSub(eye, dScale(a, (c.azimuth & 1)? -4.0 : 4.0)));
        } break;
        case DG_FIXED_UP:
        {
            // up (length 1.7) within the angle of +-normal; fallback the world up of the normal
            D3 n = c.variant? dNorm(d3(-0.6, 0.3, 0.5)) : dNorm(d3(0.2, 0.5, 1.0));
            b->facing = RBL_FACING_FIXED;
            b->axis = dgF(n);
            b->up = dgF(dScale(dgTilt(dScale(n, sd), d3(0, 1, 0), c.angle, az), 1.7));
        } break;
        case DG_FIXED_NORMAL:
        {
            // default up (+Y); normal within the angle of +-Y (axis length 1 or 3)
            b->facing = RBL_FACING_FIXED;
            b->axis = dgF(dScale(dgTilt(dScale(Y, sd), d3(0, 0, -sd), c.angle, az), c.variant? 3.0 : 1.0));
        } break;
        case DG_TILT_LIGHT:
        {
            // upright AXIS billboard; a directional light (or a point light 20 units away) within the
            // angle of its pivot line (its right), minimum cast angle 30 degrees
            b->facing = RBL_FACING_AXIS;
            D3 toEye = dSub(d3f(c.camera.position), d3f(b->position));
            D3 n0 = dNorm(dSub(toEye, dScale(Y, dDot(toEye, Y)))), r0 = dCross(Y, n0);
            D3 l = dgTilt(dScale(r0, sd), n0, c.angle, az);
            if (c.variant) { D3 p = dAdd(d3f(b->position), dScale(l, 20.0)); c.light = (Vector4){ (float)p.x, (float)p.y, (float)p.z, 1.0f }; }
            else c.light = (Vector4){ (float)l.x, (float)l.y, (float)l.z, 0.0f };
            c.minSin = sinf(30.0f*PI/180.0f);
        } break;
        case DG_CAMERA_TARGET:
        {
            // target reaching the position along one of 6 x 4 directions; length = the angle slot
            D3 eye = c.variant? d3(0.5, 0.25, 0.125) : d3(3.0, 6.0, 25.0);
            D3 dir = dgTilt(dScale(Y, sd), d3(0, 0, 1), 1.0, az);
            c.camera = makeCamera(dgF(eye), dgF(dSub(eye, dScale(dir, c.angle))), (Vector3){ 0.1f, 1.0f, 0.0f });
            b->facing = RBL_FACING_CAMERA_POSITION;
            b->position = dgF(dSub(eye, dScale(dir, 3.0)));
        } break;
        case DG_POSITION_EYE:
        {
            D3 dir = dgTilt(dScale(B, sd), U, 1.0, az);
            if (c.variant) c.camera = makeCamera((Vector3){ 0.5f, 0.25f, 0.125f }, (Vector3){ -1.0f, 0.5f, -7.0f }, (Vector3){ 0.1f, 1.0f, 0.0f });
            b->facing = RBL_FACING_CAMERA_POSITION;
            b->position = dgF(dSub(d3f(c.camera.position), dScale(dir, c.angle)));
        } break;
        default: break;
    }
    return c;
}

// Case k (0 .. DG_CASES-1) of a configuration
static inline DgCase dgCase(int config, int k)
{
    int angleIndex = (k/DG_AZIMUTHS)%DG_ANGLES, variant = (k/(DG_AZIMUTHS*DG_ANGLES))%2;
    int side = (k/(DG_AZIMUTHS*DG_ANGLES*2))? -1 : 1;
    return dgCaseAt(config, side, variant, k%DG_AZIMUTHS, dgAngle(config, angleIndex));
}

// Approach angle at which the configuration's blend weight is 1/2, where on the side whose direction
// opposes the fallback's the two cancel (the one point any continuous blend must have: a direction
// field turning once around the axis cannot shrink continuously to a constant); -1 for none. Dense
// probes span +-2% around it: DG_DENSE angles for each side, variant and azimuth.
#define DG_DENSE 101
static inline double dgCancelAngle(int config)
{
    if (config == DG_CAMERA_UP) return asin(0.5*(REF_CAMERA_BLEND_LO + REF_CAMERA_BLEND_HI));
    if ((config == DG_TILT_LIGHT) || dgIsOffset(config)) return -1.0;      // the tilt's blend never cancels
    return asin(0.5*(REF_BLEND_LO + REF_BLEND_HI));
}
static inline DgCase dgDenseCase(int config, int k)
{
    int i = k%DG_DENSE, azimuth = (k/DG_DENSE)%DG_AZIMUTHS, variant = (k/(DG_DENSE*DG_AZIMUTHS))%2;
    int side = (k/(DG_DENSE*DG_AZIMUTHS*2))? -1 : 1;
    return dgCaseAt(config, side, variant, azimuth, dgCancelAngle(config)*(1.0 + 0.02*(2.0*i/(DG_DENSE - 1) - 1.0)));
}
#define DG_DENSE_CASES (DG_DENSE*DG_AZIMUTHS*DG_VARIANTS)

// The CPU path's quad for a case (the shadow pass's cast for DG_TILT_LIGHT); false if skipped
static inline bool dgCpuQuad(const DgCase *c, int texW, int texH, RblVertex q[4])
{
    RblCameraFrame view = RblGetCameraFrame(c->camera);
    rbl__Cast cast;
    memset(&cast, 0, sizeof(cast));         // camera-facing casters (the instanced capture's facing code carries no flags)
    cast.light = c->light; cast.minSin = c->minSin;
    rbl__FrameCache cache;
    cache.facing = -1;
    return rbl__billboardVertices(&view, (c->minSin > 0.0f)? &cast : NULL, &cache, texW, texH, &c->billboard, q);
}

#endif
