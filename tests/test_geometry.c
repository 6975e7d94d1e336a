// Geometry specification (CPU only): corners, UVs, normals and tangents of every facing mode,
// against a double-precision reference written independently here, plus the hard cases.
// Included by test_cpu_main.c (one translation unit with the implementation).

#include "reference.h"
#include "degenerate.h"

static RblBillboard randomBillboard(unsigned int *seed, int facing)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.facing = facing;
    b.position = (Vector3){ rtRandomRange(seed, -20, 20), rtRandomRange(seed, -5, 5), rtRandomRange(seed, -20, 20) };
    b.size = (Vector2){ rtRandomRange(seed, 0.1f, 4.0f), rtRandomRange(seed, 0.1f, 4.0f) };
    b.origin = (Vector2){ rtRandomRange(seed, -1.0f, 2.0f), rtRandomRange(seed, -1.0f, 2.0f) };
    b.rotation = (rtRandom(seed) & 1)? rtRandomRange(seed, -360.0f, 360.0f) : 0.0f;
    b.source = (Rectangle){ rtRandomRange(seed, 0, 128), rtRandomRange(seed, 0, 128), rtRandomRange(seed, 1, 128), rtRandomRange(seed, 1, 128) };
    if (facing == RBL_FACING_AXIS) b.axis = (Vector3){ rtRandomRange(seed, -1, 1), rtRandomRange(seed, 0.2f, 1), rtRandomRange(seed, -1, 1) };
    if (facing == RBL_FACING_FIXED)
    {
        b.axis = (Vector3){ rtRandomRange(seed, -1, 1), rtRandomRange(seed, -1, 1), rtRandomRange(seed, 0.3f, 1) };
        b.up = (Vector3){ rtRandomRange(seed, -0.2f, 0.2f), 1.0f, rtRandomRange(seed, -0.2f, 0.2f) };
    }
    return b;
}

// Frame invariants every emitted vertex must satisfy
static void checkFrame(const RblVertex q[4], const char *what)
{
    for (int i = 0; i < 4; i++)
    {
        const float *all = q[i].position;
        for (int k = 0; k < 12; k++) RT_CHECK(rtFinite(all[k]), "%s: vertex %d float %d not finite", what, i, k);
        D3 n = vecOf(q[i].normal), t = vecOf(q[i].tangent);
        RT_CHECK(fabs(dLen(n) - 1.0) <= 1e-5, "%s: |N| = %.8f", what, dLen(n));
        RT_CHECK(fabs(dLen(t) - 1.0) <= 1e-5, "%s: |T| = %.8f", what, dLen(t));
        RT_CHECK(fabs(dDot(n, t)) < 1e-5, "%s: N.T = %.3g", what, dDot(n, t));
        RT_CHECK((q[i].tangent[3] == 1.0f) || (q[i].tangent[3] == -1.0f), "%s: w = %f", what, q[i].tangent[3]);
    }
}

// ---- tests --------------------------------------------------------------------------------------
static void test_geometry_corners_match_double_reference_in_every_mode(void)
{
    Camera3D cam = makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.1f, 1.0f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    unsigned int seed = 12345u;
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    {
        double worst = 0.0;
        for (int n = 0; n < 500; n++)
        {
            RblBillboard b = randomBillboard(&seed, facing);
            RblVertex q[4];
            RT_CHECK(RblBillboardVertices(&view, 256, 256, &b, q), "mode %d: billboard %d skipped", facing, n);
            D3 ref[4], N;
            refQuad(cam, &b, ref, &N);
            double scale = fabs(b.size.x) + fabs(b.size.y) + fabs(b.origin.x) + fabs(b.origin.y) + dLen(d3f(b.position));
            for (int i = 0; i < 4; i++)
            {
                double e = v3dist(q[i].position, ref[i])/scale;
                if (e > worst) worst = e;
            }
            RT_CHECK(dDot(vecOf(q[0].normal), N) > 1.0 - 1e-6, "mode %d: normal differs from reference", facing);
            checkFrame(q, "random");
        }
        RT_CHECK(worst < 1e-6, "mode %d: worst relative corner error %.3g", facing, worst);
    }
}

static void test_geometry_camera_modes_face_the_eye(void)
{
    Camera3D cam = makeCamera((Vector3){ 0.0f, 2.0f, 10.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    unsigned int seed = 99u;
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_AXIS; facing++)
    {
        for (int n = 0; n < 100; n++)
        {
            RblBillboard b = randomBillboard(&seed, facing);
            b.position.z = rtRandomRange(&seed, -30.0f, 5.0f);
            RblVertex q[4];
            RblBillboardVertices(&view, 64, 64, &b, q);
            D3 toEye = dSub(d3f(cam.position), d3f(b.position));
            RT_CHECK(dDot(vecOf(q[0].normal), toEye) > 0.0, "mode %d: normal points away from the eye", facing);
            // front face is counter-clockwise seen from the eye: (p1-p0) x (p2-p0) agrees with N
            D3 e1 = dSub(vecOf(q[1].position), vecOf(q[0].position)), e2 = dSub(vecOf(q[2].position), vecOf(q[0].position));
            RT_CHECK(dDot(dCross(e1, e2), vecOf(q[0].normal)) > 0.0, "mode %d: winding is not counter-clockwise", facing);
        }
    }
    // Camera-position mode differs from camera-plane off-centre (that is the point of it)
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ 8.0f, 0.0f, 0.0f }; b.size = (Vector2){ 1.0f, 1.0f };
    RblVertex plane[4], toward[4];
    RblBillboardVertices(&view, 1, 1, &b, plane);
    b.facing = RBL_FACING_CAMERA_POSITION;
    RblBillboardVertices(&view, 1, 1, &b, toward);
    RT_CHECK(dDot(vecOf(plane[0].normal), vecOf(toward[0].normal)) < 0.95, "camera-position mode should turn toward the eye off-centre");
}

// Tangent = world +U and handedness, derived from the emitted positions and UVs the way raylib's
// GenMeshTangents does (independent of how the header computes it), for every flip and rotated frame.
static void test_geometry_tangent_follows_plus_u_under_every_flip_and_rotated_frame(void)
{
    Camera3D cam = makeCamera((Vector3){ 2.0f, 3.0f, 9.0f }, (Vector3){ 0.0f, 1.0f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    int combos = 0;
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    for (int mask = 0; mask < 32; mask++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.facing = facing;
        b.position = (Vector3){ 0.5f, 1.0f, -1.0f };
        b.size = (Vector2){ (mask & 1)? -1.5f : 1.5f, (mask & 2)? -2.0f : 2.0f };
        b.source = (Rectangle){ 16, 32, (mask & 4)? -48.0f : 48.0f, (mask & 8)? -24.0f : 24.0f };
        b.flags = (mask & 16)? RBL_FRAME_ROTATED : 0;
        b.rotation = 30.0f;
        b.axis = (facing == RBL_FACING_FIXED)? (Vector3){ 0.3f, 0.2f, 1.0f } : (Vector3){ 0, 0, 0 };
        RblVertex q[4];
        RT_CHECK(RblBillboardVertices(&view, 128, 128, &b, q), "skipped");
        checkFrame(q, "flip");
        D3 e1 = dSub(vecOf(q[1].position), vecOf(q[0].position)), e2 = dSub(vecOf(q[3].position), vecOf(q[0].position));
        double s1 = q[1].texcoord[0] - q[0].texcoord[0], t1 = q[1].texcoord[1] - q[0].texcoord[1];
        double s2 = q[3].texcoord[0] - q[0].texcoord[0], t2 = q[3].texcoord[1] - q[0].texcoord[1];
        double r = 1.0/(s1*t2 - s2*t1);
        D3 sdir = dScale(dSub(dScale(e1, t2), dScale(e2, t1)), r);     // world d/du
        D3 tdir = dScale(dSub(dScale(e2, s1), dScale(e1, s2)), r);     // world d/dv
        D3 T = vecOf(q[0].tangent), N = vecOf(q[0].normal);
        RT_CHECK(dDot(T, dNorm(sdir)) > 0.9999, "mode %d mask %d: tangent is not +U (dot %.5f)", facing, mask, dDot(T, dNorm(sdir)));
        double hand = dDot(dCross(N, T), tdir) < 0.0? -1.0 : 1.0;
        RT_CHECK(hand == q[0].tangent[3], "mode %d mask %d: handedness %g, UVs say %g", facing, mask, q[0].tangent[3], hand);
        combos++;
    }
    RT_CHECK(combos == 128, "ran %d combinations", combos);
}

static void test_geometry_uvs_match_raylib_layout_and_mirror_inside_the_source(void)
{
    Camera3D cam = makeCamera((Vector3){ 0, 0, 5 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 });
    RblCameraFrame view = RblGetCameraFrame(cam);
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 3.0f, 1.0f };           // deliberately not the source size in texels
    b.origin = (Vector2){ 1.5f, 0.0f };
    b.source = (Rectangle){ 32, 64, 64, 32 };
    RblVertex q[4], m[4];
    RblBillboardVertices(&view, 256, 128, &b, q);
    // raylib: 0 = (x, y+h), 1 = (x+w, y+h), 2 = (x+w, y), 3 = (x, y), divided by the texture size
    const float expect[4][2] = { { 32/256.0f, 96/128.0f }, { 96/256.0f, 96/128.0f }, { 96/256.0f, 64/128.0f }, { 32/256.0f, 64/128.0f } };
    for (int i = 0; i < 4; i++) RT_CHECK(rtNear(q[i].texcoord[0], expect[i][0], 1e-7) && rtNear(q[i].texcoord[1], expect[i][1], 1e-7), "uv %d", i);
    // Negative size: same footprint and pivot, u mirrored within [x, x+w] (raylib would shift by size.x)
    b.size.x = -3.0f;
    RblBillboardVertices(&view, 256, 128, &b, m);
    for (int i = 0; i < 4; i++)
    {
        RT_CHECK(v3dist(m[i].position, vecOf(q[i].position)) < 1e-6, "flipped footprint moved at corner %d", i);
        RT_CHECK(rtNear(m[i].texcoord[0], (32 + 96)/256.0f - q[i].texcoord[0], 1e-7), "flipped u %d = %f", i, m[i].texcoord[0]);
        RT_CHECK(m[i].texcoord[0] >= 32/256.0f - 1e-7 && m[i].texcoord[0] <= 96/256.0f + 1e-7, "flipped u left the source rectangle");
        RT_CHECK(rtNear(m[i].texcoord[1], q[i].texcoord[1], 1e-7), "flipped v changed");
    }
    // A negative source width flips the same way; both together cancel
    b.size.x = 3.0f; b.source.width = -64.0f;
    RblBillboardVertices(&view, 256, 128, &b, m);
    RT_CHECK(rtNear(m[0].texcoord[0], 96/256.0f, 1e-7), "negative source width should mirror");
    b.size.x = -3.0f;
    RblBillboardVertices(&view, 256, 128, &b, m);
    RT_CHECK(rtNear(m[0].texcoord[0], 32/256.0f, 1e-7), "two mirrors should cancel");
    // Rotated frame: the sprite's top-left texel sits at the frame's top-right (packed clockwise)
    b.size.x = 3.0f; b.source.width = 64.0f; b.flags = RBL_FRAME_ROTATED;
    RblBillboardVertices(&view, 256, 128, &b, m);
    RT_CHECK(rtNear(m[3].texcoord[0], 96/256.0f, 1e-7) && rtNear(m[3].texcoord[1], 64/128.0f, 1e-7), "rotated frame: top-left corner uv (%f,%f)", m[3].texcoord[0], m[3].texcoord[1]);
    RT_CHECK(rtNear(m[0].texcoord[0], 32/256.0f, 1e-7) && rtNear(m[0].texcoord[1], 64/128.0f, 1e-7), "rotated frame: bottom-left corner uv (%f,%f)", m[0].texcoord[0], m[0].texcoord[1]);
    // Zero source = whole texture
    memset(&b.source, 0, sizeof(b.source)); b.flags = 0;
    RblBillboardVertices(&view, 256, 128, &b, m);
    RT_CHECK(m[0].texcoord[0] == 0.0f && m[0].texcoord[1] == 1.0f && m[2].texcoord[0] == 1.0f && m[2].texcoord[1] == 0.0f, "zero source should span the texture");
}

static void test_geometry_rounded_normals_bend_outward_and_stay_orthonormal(void)
{
    Camera3D cam = makeCamera((Vector3){ 0, 0, 5 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 });
    RblCameraFrame view = RblGetCameraFrame(cam);
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 2.0f, 2.0f }; b.origin = (Vector2){ 1.0f, 1.0f };
    for (int cyl = 0; cyl < 2; cyl++)
    for (int k = 0; k <= 4; k++)
    {
        b.roundness = k/4.0f;
        b.flags = cyl? RBL_ROUND_CYLINDER : 0;
        RblVertex q[4];
        RblBillboardVertices(&view, 1, 1, &b, q);
        checkFrame(q, "rounded");
        D3 mean = d3(0, 0, 0);
        for (int i = 0; i < 4; i++)
        {
            D3 n = vecOf(q[i].normal), p = vecOf(q[i].position);   // quad centred on the origin
            double lean = dDot(n, d3(p.x, cyl? 0.0 : p.y, 0.0));
            if (k == 0) RT_CHECK(fabs(lean) < 1e-6, "flat normal leans");
            else RT_CHECK(lean > 0.0, "rounded normal %d does not lean outward", i);
            mean = dAdd(mean, n);
        }
        RT_CHECK(dDot(dNorm(mean), d3(0, 0, 1)) > 1.0 - 1e-6, "mean of corner normals should stay the flat normal");
        double expected = (k == 4)? (cyl? 45.0 : 54.7356) : -1.0;
        double angle = acos(q[0].normal[2])*180.0/PI;
        if (expected > 0.0) RT_CHECK(fabs(angle - expected) < 1e-3, "full roundness corner angle %.4f, want %.4f", angle, expected);
    }
}

// ---- hard cases -----------------------------------------------------------------------------------
static void test_hard_camera_looking_straight_up_or_down_gets_a_stable_frame(void)
{
    const float ys[2] = { 10.0f, -10.0f };
    for (int k = 0; k < 2; k++)
    {
        Camera3D cam = makeCamera((Vector3){ 1.0f, ys[k], 2.0f }, (Vector3){ 1.0f, 0.0f, 2.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
        RblCameraFrame view = RblGetCameraFrame(cam);
        RT_CHECK(fabs(dLen(d3f(view.right)) - 1.0) < 1e-6 && fabs(dLen(d3f(view.up)) - 1.0) < 1e-6, "view frame not unit");
        RT_CHECK(fabs(dDot(d3f(view.right), d3f(view.up))) < 1e-6, "view frame not orthogonal");
        // Looking down, screen-up is -Z (north); looking up it is +Z
        RT_CHECK(view.up.z == ((k == 0)? -1.0f : 1.0f), "fallback up is %f,%f,%f", view.up.x, view.up.y, view.up.z);
        for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.facing = facing; b.size = (Vector2){ 1, 1 }; b.position = (Vector3){ 1.0f, 0.0f, 2.0f };
            RblVertex q[4];
            RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "skipped");
            checkFrame(q, "looking along up");
        }
    }
}

static void test_hard_target_equals_position_and_billboard_at_the_eye(void)
{
    Camera3D cam = makeCamera((Vector3){ 1, 2, 3 }, (Vector3){ 1, 2, 3 }, (Vector3){ 0, 1, 0 });
    RblCameraFrame view = RblGetCameraFrame(cam);
    RT_CHECK(view.back.z == 1.0f, "target == position: view should fall back to looking down -Z");
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.facing = facing; b.size = (Vector2){ 1, 1 };
        b.position = cam.position;              // centre exactly at the eye
        RblVertex q[4];
        RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "mode %d skipped", facing);
        checkFrame(q, "at the eye");
    }
    // Axis mode with the eye on the axis (and looking along it): still a valid upright frame
    Camera3D above = makeCamera((Vector3){ 0, 10, 0 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 0, -1 });
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.facing = RBL_FACING_AXIS; b.size = (Vector2){ 1, 2 };
    RblVertex q[4];
    RblCameraFrame aboveView = RblGetCameraFrame(above);
    RT_CHECK(RblBillboardVertices(&aboveView, 8, 8, &b, q), "axis mode, eye on axis: skipped");
    checkFrame(q, "eye on axis");
    RT_CHECK(fabs(q[3].position[1] - q[0].position[1] - 2.0f) < 1e-6, "axis-locked billboard must stay upright");
}

// Orthonormality errors of one near-degenerate case: camera frame, normal/tangent, quad edges and
// normal (CAMERA_PLANE with a caller up keeps raylib's parallelogram: its edges are not perpendicular,
// the normal is perpendicular to both), unit lengths; NaN sticks
typedef struct { double view, nt, edges, unit; } DgOrtho;
static void dgMeasureOrtho(const DgCase *c, DgOrtho *o)
{
    RblCameraFrame view = RblGetCameraFrame(c->camera);
    D3 vr = d3f(view.right), vu = d3f(view.up), vb = d3f(view.back);
    double e = fmax(fabs(dDot(vr, vu)), fmax(fabs(dDot(vr, vb)), fabs(dDot(vu, vb))));
    e = fmax(e, fmax(fabs(dLen(vr) - 1.0), fmax(fabs(dLen(vu) - 1.0), fabs(dLen(vb) - 1.0))));
    if (!(e <= o->view)) o->view = e;
    RblVertex q[4];
    RT_CHECK(dgCpuQuad(c, 64, 64, q), "%s skipped", dgNames[0]);
    D3 e1 = dSub(vecOf(q[1].position), vecOf(q[0].position)), e2 = dSub(vecOf(q[3].position), vecOf(q[0].position));
    e1 = dScale(e1, 1.0/dLen(e1)); e2 = dScale(e2, 1.0/dLen(e2));
    bool parallelogram = (c->billboard.facing == RBL_FACING_CAMERA_PLANE) && (dDot(d3f(c->billboard.up), d3f(c->billboard.up)) > 1e-24);
    for (int i = 0; i < 4; i++)
    {
        D3 n = vecOf(q[i].normal), t = vecOf(q[i].tangent);
        e = fmax(fabs(dLen(n) - 1.0), fabs(dLen(t) - 1.0));
        if (!(e <= o->unit)) o->unit = e;
        e = fabs(dDot(n, t));
        if (!(e <= o->nt)) o->nt = e;
    }
    D3 n = vecOf(q[0].normal);
    e = fmax(fabs(dDot(n, e1)), fabs(dDot(n, e2)));
    if (!parallelogram) e = fmax(e, fabs(dDot(e1, e2)));
    if (!(e <= o->edges)) o->edges = e;
}

// Near-degenerate frames (tests/degenerate.h: every fallback approached from 5 degrees down to
// 1e-7 rad, both sides, six azimuths, and densely through each blend's cancelling point): the camera
// frame, normal, tangent and quad edges stay orthonormal within 1e-5
static void test_hard_near_degenerate_frames_are_orthonormal(void)
{
    double worstAll = 0.0;
    for (int config = 0; config < DG_CONFIGS; config++)
    {
        DgOrtho o = { 0.0, 0.0, 0.0, 0.0 };
        for (int k = 0; k < DG_CASES; k++) { DgCase c = dgCase(config, k); dgMeasureOrtho(&c, &o); }
        int dense = (dgCancelAngle(config) > 0.0)? DG_DENSE_CASES : 0;
        for (int k = 0; k < dense; k++) { DgCase c = dgDenseCase(config, k); dgMeasureOrtho(&c, &o); }
        double worst = fmax(fmax(o.view, o.nt), fmax(o.edges, o.unit));
        if (!(worst <= worstAll)) worstAll = worst;
        printf("    %-32s |N.T| %.2e, quad edges/normal %.2e, unit %.2e, camera frame %.2e\n", dgNames[config], o.nt, o.edges, o.unit, o.view);
        RT_CHECK(worst <= 1e-5, "%s: |N.T| %.3g, edges %.3g, unit %.3g, camera frame %.3g", dgNames[config], o.nt, o.edges, o.unit, o.view);
    }
    printf("    near-degenerate sweeps (%d cases, and %d through the cancelling points): worst orthonormality error %.2e\n",
           DG_CASES*DG_CONFIGS, DG_DENSE_CASES*7, worstAll);
}

// The same sweeps against the double reference of the documented blend (reference.h, written from
// the README): corners within 1e-5 of the quad's size, normals within 1e-5
static void test_hard_near_degenerate_frames_follow_the_documented_blend(void)
{
    double worstAll = 0.0;
    for (int config = 0; config < DG_CONFIGS; config++)
    {
        double worstPos = 0.0, worstN = 0.0, atAngle = 0.0;
        int atAz = 0, atSide = 0, atVariant = 0;
        for (int k = 0; k < DG_CASES; k++)
        {
            DgCase c = dgCase(config, k);
            c.billboard.rotation = (c.azimuth & 1)? 37.5f : 0.0f;
            RblVertex q[4];
            RT_CHECK(dgCpuQuad(&c, 64, 64, q), "%s case %d skipped", dgNames[config], k);
            D3 ref[4], N;
            refQuadCast(c.camera, &c.billboard, c.light, c.minSin, ref, &N);
            double scale = fabs(c.billboard.size.x) + fabs(c.billboard.size.y) + fabs(c.billboard.origin.x) + fabs(c.billboard.origin.y);
            double e = 0.0;
            for (int i = 0; i < 4; i++) e = fmax(e, v3dist(q[i].position, ref[i])/scale);
            double en = dLen(dSub(vecOf(q[0].normal), N));
            if (!(fmax(e, en) <= fmax(worstPos, worstN))) { atAngle = c.angle; atAz = c.azimuth*60; atSide = c.side; atVariant = c.variant; }
            if (!(e <= worstPos)) worstPos = e;
            if (!(en <= worstN)) worstN = en;
        }
        worstAll = fmax(worstAll, fmax(worstPos, worstN));
        printf("    %-32s corners %.2e of the size, normal %.2e (worst at %.3g, azimuth %d, side %d, variant %d)\n",
               dgNames[config], worstPos, worstN, atAngle, atAz, atSide, atVariant);
        RT_CHECK(worstPos <= 1e-5 && worstN <= 1e-5, "%s: corners %.3g, normal %.3g from the double reference", dgNames[config], worstPos, worstN);
    }
    printf("    near-degenerate sweeps (%d cases): worst difference from the reference blend %.2e\n", DG_CASES*DG_CONFIGS, worstAll);
}

// The fallbacks themselves, reached exactly: the camera looking along its up gets +Y for a view along
// X or Z (-Z / +Z along +Y / -Y: the test above), FIXED with up along a normal along X gets +Y, and a
// CAMERA_PLANE caller up along the camera's right keeps its length along right: the quad collapses
// to a line as raylib's does, its normal the view's back
static void test_hard_exact_degenerate_frames_are_the_documented_fallbacks(void)
{
    const Vector3 views[4] = { { 10, 0, 0 }, { -10, 0, 0 }, { 0, 0, 10 }, { 0, 0, -10 } };
    for (int i = 0; i < 4; i++)
    {
        Vector3 dir = { views[i].x/10.0f, views[i].y/10.0f, views[i].z/10.0f };
        RblCameraFrame v = RblGetCameraFrame(makeCamera(views[i], (Vector3){ 0, 0, 0 }, dir));
        RT_CHECK(v.up.x == 0.0f && v.up.y == 1.0f && v.up.z == 0.0f, "view along (%g, %g, %g) with up along it: screen-up (%g, %g, %g), want +Y",
                 dir.x, dir.y, dir.z, v.up.x, v.up.y, v.up.z);
    }
    RblCameraFrame view = RblGetCameraFrame(makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.1f, 1.0f, 0.0f }));
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.5f, 2.0f }; b.origin = (Vector2){ 0.75f, 0.5f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 1, 0, 0 }; b.up = (Vector3){ 3, 0, 0 };
    RblVertex q[4];
    RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "FIXED skipped");
    checkFrame(q, "FIXED up along the normal");
    D3 up = dSub(vecOf(q[3].position), vecOf(q[0].position));
    RT_CHECK(fabs(up.x) < 1e-6 && fabs(up.y - 2.0) < 1e-6 && fabs(up.z) < 1e-6, "FIXED normal +X, up +X: up edge (%g, %g, %g), want +Y x 2", up.x, up.y, up.z);
    b.facing = RBL_FACING_CAMERA_PLANE; b.axis = (Vector3){ 0, 0, 0 };
    b.up = (Vector3){ 2.0f*view.right.x, 2.0f*view.right.y, 2.0f*view.right.z };
    RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "CAMERA_PLANE skipped");
    checkFrame(q, "CAMERA_PLANE up along right");
    D3 e1 = dSub(vecOf(q[1].position), vecOf(q[0].position)), e2 = dSub(vecOf(q[3].position), vecOf(q[0].position));
    double area = dLen(dCross(e1, e2))/(dLen(e1)*dLen(e2));
    RT_CHECK(area < 1e-5, "CAMERA_PLANE up along right: the quad should collapse (sine between edges %.3g)", area);
    RT_CHECK(fabs(dLen(e2) - 4.0) < 1e-5, "CAMERA_PLANE up along right: up edge %.7f long, want |up| x height = 4", dLen(e2));
    RT_CHECK(dDot(vecOf(q[0].normal), d3f(view.back)) > 1.0 - 1e-6, "CAMERA_PLANE up along right: normal should be the view's back");
}

static void test_hard_zero_negative_and_huge_sizes(void)
{
    Camera3D cam = makeCamera((Vector3){ 0, 0, 5 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 });
    RblCameraFrame view = RblGetCameraFrame(cam);
    // Up to the documented bound 2^60 (1.15e18) every size is accepted with finite corners
    const float sizes[][2] = { { 0, 0 }, { 0, 1 }, { -1, -1 }, { -1e-30f, 1e-30f }, { 1e18f, 1e18f }, { -1e18f, 1.1e18f } };
    for (int i = 0; i < (int)(sizeof(sizes)/sizeof(sizes[0])); i++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.size = (Vector2){ sizes[i][0], sizes[i][1] };
        RblVertex q[4];
        RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "size %g,%g skipped", sizes[i][0], sizes[i][1]);
        checkFrame(q, "sizes");
    }
    // Beyond it (just above 2^60, 1e30, corners that overflow float) they are skipped, not written as Inf
    const float beyond[][4] = { { 1.16e18f, 1.0f, 0.0f, 0.0f }, { 1.0f, -1e30f, 0.0f, 0.0f }, { 3e38f, 3e38f, -3e38f, 0.0f } };
    for (int i = 0; i < 3; i++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.size = (Vector2){ beyond[i][0], beyond[i][1] }; b.origin = (Vector2){ beyond[i][2], beyond[i][3] };
        RblVertex q[4];
        memset(q, 0x5A, sizeof(q));
        RT_CHECK(!RblBillboardVertices(&view, 8, 8, &b, q), "size %g,%g beyond 2^60 must be skipped", beyond[i][0], beyond[i][1]);
        RT_CHECK(((unsigned char *)q)[0] == 0x5A && ((unsigned char *)q)[sizeof(q) - 1] == 0x5A, "skipped quad must leave the output untouched");
    }
}

static void test_hard_far_from_origin_keeps_relative_precision(void)
{
    Vector3 far = { 1e5f, -1e5f, 1e5f };
    Camera3D cam = makeCamera((Vector3){ far.x + 3.0f, far.y + 2.0f, far.z + 10.0f }, far, (Vector3){ 0, 1, 0 });
    RblCameraFrame view = RblGetCameraFrame(cam);
    unsigned int seed = 7u;
    double worst = 0.0;
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    for (int n = 0; n < 200; n++)
    {
        RblBillboard b = randomBillboard(&seed, facing);
        b.position = (Vector3){ far.x + b.position.x, far.y + b.position.y, far.z + b.position.z };
        RblVertex q[4];
        RblBillboardVertices(&view, 256, 256, &b, q);
        checkFrame(q, "far");
        D3 ref[4], N;
        refQuad(cam, &b, ref, &N);
        for (int i = 0; i < 4; i++)
        {
            double e = v3dist(q[i].position, ref[i])/dLen(ref[i]);
            if (e > worst) worst = e;
        }
    }
    // float carries ~6e-8 relative; a few roundings of the corner sum stay well under 4e-7
    RT_CHECK(worst < 4e-7, "worst relative corner error at 1e5: %.3g", worst);
}

static void test_hard_degenerate_source_and_texture_size(void)
{
    RblCameraFrame view = RblGetCameraFrame(makeCamera((Vector3){ 0, 0, 5 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 }));
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1, 1 };
    b.source = (Rectangle){ 10, 10, 0, 0 };     // zero area (not the all-zero "whole texture")
    RblVertex q[4];
    RT_CHECK(RblBillboardVertices(&view, 32, 32, &b, q), "zero-area source should still draw (one texel)");
    checkFrame(q, "zero-area source");
    for (int i = 0; i < 4; i++) RT_CHECK(q[i].texcoord[0] == 10/32.0f && q[i].texcoord[1] == 10/32.0f, "uv should collapse to the texel");
    memset(q, 0x5A, sizeof(q));
    RT_CHECK(!RblBillboardVertices(&view, 0, 32, &b, q), "zero texture width must be rejected");
    RT_CHECK(!RblBillboardVertices(&view, 32, -1, &b, q), "negative texture height must be rejected");
    RT_CHECK(((unsigned char *)q)[0] == 0x5A, "rejected quad must leave the output untouched");
}

static void test_hard_nan_or_inf_in_any_input_is_skipped(void)
{
    RblCameraFrame view = RblGetCameraFrame(makeCamera((Vector3){ 0, 0, 5 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 }));
    RblBillboard good;
    memset(&good, 0, sizeof(good));
    good.size = (Vector2){ 1, 1 };
    const float bad[2] = { NAN, INFINITY };
    int fields = (int)(sizeof(RblBillboard)/sizeof(float));
    int rejected = 0, probed = 0;
    for (int f = 0; f < fields; f++)
    {
        size_t off = (size_t)f*sizeof(float);
        // skip the tint (bytes), facing and flags (ints): only float fields take NaN
        if (off >= offsetof(RblBillboard, tint) && off < offsetof(RblBillboard, up)) continue;
        if (off >= offsetof(RblBillboard, flags)) continue;
        for (int k = 0; k < 2; k++)
        {
            RblBillboard b = good;
            memcpy((char *)&b + off, &bad[k], sizeof(float));
            RblVertex q[4];
            memset(q, 0x5A, sizeof(q));
            bool drawn = RblBillboardVertices(&view, 8, 8, &b, q);
            probed++;
            if (!drawn) rejected++;
            RT_CHECK(!drawn && ((unsigned char *)q)[0] == 0x5A, "float field %d = %f was not skipped", f, bad[k]);
        }
    }
    RT_CHECK(probed >= 34 && rejected == probed, "probed %d float fields, rejected %d", probed, rejected);
    // A bad camera also never produces NaN: the view falls back
    Camera3D nanCam = makeCamera((Vector3){ 0, 0, 5 }, (Vector3){ 0, 0, 0 }, (Vector3){ NAN, 1, 0 });
    RblCameraFrame v = RblGetCameraFrame(nanCam);
    RT_CHECK(rtFinite(v.right.x) && rtFinite(v.up.y) && rtFinite(v.back.z), "NaN camera up leaked into the view");
    RT_CHECK(!RblBillboardVertices(&view, 8, 8, NULL, NULL), "NULL input must be rejected");
    good.facing = 99;
    RblVertex q[4];
    RT_CHECK(!RblBillboardVertices(&view, 8, 8, &good, q), "unknown facing must be rejected");
}

// ---- speed paths keep the exact results ---------------------------------------------------------
// A batch reuses a billboard's facing frame for the next one with the same facing and up; the
// result must be bit-identical to computing each billboard alone, whatever the order.
static void test_geometry_batch_frame_reuse_is_bit_identical_to_single_billboards(void)
{
    Camera3D cam = makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.1f, 1.0f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    enum { COUNT = 600 };
    // A batch without GPU buffers (no GL here): RblBatchAdd only needs the CPU side, so the test
    // builds the header's private batch state itself and registers it as loaded
    rbl__BatchState state;
    memset(&state, 0, sizeof(state));
    state.vertices = (RblVertex *)malloc(COUNT*4*sizeof(RblVertex));
    state.capacity = COUNT;
    state.runs = (rbl__BatchRun *)malloc(16*sizeof(rbl__BatchRun));
    state.runCapacity = 16;
    unsigned int stateId = rbl__liveAdd(&state);
    RT_CHECK((state.vertices != NULL) && (state.runs != NULL) && (stateId != 0), "out of memory");
    if ((state.vertices == NULL) || (state.runs == NULL)) { free(state.vertices); free(state.runs); return; }
    RblBatch batch;
    memset(&batch, 0, sizeof(batch));
    batch.state = &state;
    batch.id = stateId;
    batch.capacity = COUNT;
    // A material with a user's own shader (any non-zero program that is not the header's): accepted
    int locs[32];
    memset(locs, 0xff, sizeof(locs));
    Material material;
    memset(&material, 0, sizeof(material));
    material.shader.id = 1;
    material.shader.locs = locs;
    MaterialMap maps[12];
    memset(maps, 0, sizeof(maps));
    material.maps = maps;

    // Runs of repeated ups, a -0 up (a different key, the same frame), zero up, other modes between
    const Vector3 ups[5] = { { 0, 1, 0 }, { 0.3f, 2.0f, -0.1f }, { -0.0f, 1, 0 }, { 0, 0, 0 }, { 1e-3f, 1, 0 } };
    RblBillboard bbs[COUNT];
    unsigned int seed = 777u;
    for (int i = 0; i < COUNT; i++)
    {
        int facing = ((i/7)%5 == 4)? (int)(rtRandom(&seed)%4) : RBL_FACING_CAMERA_PLANE;
        bbs[i] = randomBillboard(&seed, facing);
        if (facing == RBL_FACING_CAMERA_PLANE) bbs[i].up = ups[(i/3)%5];
    }
    RblBeginBatch(&batch, cam);
    int mismatched = 0, skipped = 0;
    for (int i = 0; i < COUNT; i++) if (!RblBatchAdd(&batch, material, &bbs[i])) skipped++;
    for (int i = 0; i < COUNT; i++)
    {
        RblVertex alone[4];
        RblBillboardVertices(&view, 1, 1, &bbs[i], alone);
        if (memcmp(alone, &state.vertices[i*4], sizeof(alone)) != 0) mismatched++;
    }
    RT_CHECK(skipped == 0, "%d billboards skipped", skipped);
    RT_CHECK(mismatched == 0, "%d of %d batched billboards differ from RblBillboardVertices", mismatched, COUNT);
    // A new view invalidates the kept frame
    Camera3D turned = makeCamera((Vector3){ -20.0f, 2.0f, 4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
    RblCameraFrame turnedView = RblGetCameraFrame(turned);
    const RblBillboard *last = &bbs[COUNT - 1];   // CAMERA_PLANE: its frame is the one kept
    RT_CHECK(!RblBeginBatch(&batch, turned) && (batch.count == COUNT), "a Begin over pending billboards must be refused and keep them");
    RblEndBatch(&batch);     // no GL here: the GPU buffers cannot be created, nothing is drawn (one log line)
    RT_CHECK(RblBeginBatch(&batch, turned), "Begin after End refused");
    RblBatchAdd(&batch, material, last);
    RblVertex alone[4];
    RblBillboardVertices(&turnedView, 1, 1, last, alone);
    RT_CHECK(last->facing == RBL_FACING_CAMERA_PLANE, "the last billboard should be CAMERA_PLANE");
    RT_CHECK(memcmp(alone, state.vertices, sizeof(alone)) == 0, "the frame kept from the previous camera was reused");
    RblEndBatch(&batch);     // no GPU buffer: draws nothing, must not crash
    rbl__liveRemove(stateId);
    free(state.vertices);
    free(state.runs);
}

// Rotation uses a sin/cos in degrees with an exact reduction: quadrant angles are exact and every
// angle is within 1.5e-7 of the double-precision value (sinf(deg*DEG2RAD) is off by up to 3.6e-5
// at 37000 degrees, from rounding the product)
static void test_geometry_rotation_sin_cos_is_exact_at_quadrants_and_within_1_5e_7(void)
{
    for (int k = -8; k <= 8; k++)
    {
        float s, c;
        rbl__sinCosDeg(90.0f*(float)k, &s, &c);
        int q = ((k%4) + 4)%4;
        float es = (q == 1)? 1.0f : ((q == 3)? -1.0f : 0.0f), ec = (q == 0)? 1.0f : ((q == 2)? -1.0f : 0.0f);
        RT_CHECK((s == es) && (c == ec), "%d degrees: sin %.9g cos %.9g", 90*k, s, c);
    }
    double worst = 0.0;
    for (int i = -400000; i <= 400000; i++)
    {
        float d = (float)i*0.0937f;
        float s, c;
        rbl__sinCosDeg(d, &s, &c);
        double r = (double)d*(3.14159265358979323846/180.0);
        double e = fmax(fabs(s - sin(r)), fabs(c - cos(r)));
        if (e > worst) worst = e;
    }
    RT_CHECK(worst <= 1.5e-7, "worst |error| %.3g over +-37480 degrees", worst);
    printf("    sin/cos in degrees: worst |error| %.3g over +-37480 degrees\n", worst);
    const float huge[4] = { 1e30f, -3.4e38f, 368641.0f, -1e7f };
    for (int i = 0; i < 4; i++)
    {
        float s, c;
        rbl__sinCosDeg(huge[i], &s, &c);
        double r = fmod((double)huge[i], 360.0)*(3.14159265358979323846/180.0);
        RT_CHECK(rtFinite(s) && rtFinite(c) && (fabs(s - sin(r)) < 1e-6) && (fabs(c - cos(r)) < 1e-6),
                 "%g degrees: sin %.9g cos %.9g", huge[i], s, c);
    }
}

// The batch's billboard checks and culling, four lanes at a time (SSE2 where the compiler targets it),
// against the one-at-a-time versions and an independent reference: each float word of position ..
// roundness below its bound (|x| < 2^(e - 127), NaN refused; rotation to 2^120, up and axis and
// roundness finite, CAMERA_PLANE's up below 2^30), over words drawn from each bound's edges, NaN,
// Inf, denormals and ordinary values; culling equal bit for bit (the same sums in the same order)
static double geoWordValue(unsigned int *seed, int limitExponent)
{
    unsigned int r = rtRandom(seed);
    float edge = ldexpf(1.0f, limitExponent - 127);        // the first value refused (the float's own max + 1 ulp for 255)
    switch (r % 10u)
    {
        case 0: return (limitExponent >= 255)? INFINITY : (double)edge;
        case 1: return (limitExponent >= 255)? (double)FLT_MAX : (double)nextafterf(edge, 0.0f);
        case 2: return -(double)((limitExponent >= 255)? FLT_MAX : nextafterf(edge, 0.0f));
        case 3: return NAN;
        case 4: return -INFINITY;
        case 5: return 1e-41;                               // denormal
        case 6: return -0.0;
        default: return (double)rtRandomRange(seed, -1000.0f, 1000.0f);
    }
}

static void test_hard_billboard_checks_and_culling_four_lanes_equal_one_at_a_time(void)
{
    unsigned int seed = 0x5eed1234u;
    int wrong = 0, wrongRef = 0, accepted = 0, refused = 0;
    for (int n = 0; n < 200000; n++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        int facing = (int)(rtRandom(&seed) % 4u);
        b.facing = facing;
        float *w = (float *)(void *)&b;
        bool ok = true;
        for (int i = 0; i < 21; i++)
        {
            if ((i == 12) || (i == 13)) continue;           // tint, facing
            int e = (i < 12)? ((i == 7)? 247 : 187) : ((facing == RBL_FACING_CAMERA_PLANE) && (i < 17))? 157 : 255;
            // Mostly in range (one word per billboard at an edge or beyond), so both answers occur
            double v = ((rtRandom(&seed) % 16u) == 0u)? geoWordValue(&seed, e) : (double)rtRandomRange(&seed, -100.0f, 100.0f);
            w[i] = (float)v;
            ok = ok && !isnan(w[i]) && (fabs((double)w[i]) < ldexp(1.0, e - 127));
        }
        b.tint = (Color){ (unsigned char)rtRandom(&seed), 255, 0, (unsigned char)rtRandom(&seed) };
        b.flags = rtRandom(&seed);
        bool lanes = rbl__billboardWordsOk(&b), one = rbl__billboardWordsOkScalar(&b);
        wrong += lanes != one;
        wrongRef += one != ok;
        accepted += one; refused += !one;
    }
    int cullWrong = 0, outside = 0;
    for (int n = 0; n < 200000; n++)
    {
        float cull[4][8];
        for (int k = 0; k < 8; k++) for (int e = 0; e < 4; e++) cull[e][k] = (e == 3)? rtRandomRange(&seed, 20.0f, 110.0f) : rtRandomRange(&seed, -1.0f, 1.0f);
        Vector3 c = { rtRandomRange(&seed, -60.0f, 60.0f), rtRandomRange(&seed, -60.0f, 60.0f), rtRandomRange(&seed, -60.0f, 60.0f) };
        float r2 = rtRandomRange(&seed, 0.0f, 400.0f);
        bool lanes = rbl__outsidePlanes((const float (*)[8])cull, c, r2), one = rbl__outsidePlanesScalar((const float (*)[8])cull, c, r2);
        cullWrong += lanes != one;
        outside += one;
    }
    // Spheres that touch a plane exactly (and one ulp either side): integer distances, axis normals
    for (int n = 0; n < 3000; n++)
    {
        float cull[4][8];
        for (int k = 0; k < 8; k++) for (int e = 0; e < 4; e++) cull[e][k] = (e == 3)? 1.0f : 0.0f;    // planes that keep everything
        int k = n % 8, axis = (n/8) % 3;
        cull[0][k] = cull[1][k] = cull[2][k] = 0.0f;
        cull[axis][k] = ((n/24) & 1)? -1.0f : 1.0f;
        cull[3][k] = (float)((int)(rtRandom(&seed) % 41u) - 20);
        float coord[3] = { (float)((int)(rtRandom(&seed) % 81u) - 40), (float)((int)(rtRandom(&seed) % 81u) - 40), (float)((int)(rtRandom(&seed) % 81u) - 40) };
        Vector3 c = { coord[0], coord[1], coord[2] };
        float d = cull[axis][k]*coord[axis] + cull[3][k];
        float r2 = d*d, pick = (float)(n % 3);
        if (pick == 1.0f) r2 = nextafterf(r2, 0.0f);
        if (pick == 2.0f) r2 = nextafterf(r2, INFINITY);
        bool lanes = rbl__outsidePlanes((const float (*)[8])cull, c, r2), one = rbl__outsidePlanesScalar((const float (*)[8])cull, c, r2);
        bool ref = (d < 0.0f) && ((double)d*(double)d > (double)r2);
        cullWrong += (lanes != one) + (one != ref);
        outside += one;
    }
#if defined(RBL__SSE2)
    const char *kind = "SSE2";
#else
    const char *kind = "plain C (no SSE2 here: the two are one)";
#endif
    printf("    %s: 200000 billboards (%d accepted, %d refused): %d differ from one at a time, %d from the reference; 203000 spheres (%d outside, 3000 touching a plane): %d differ\n",
           kind, accepted, refused, wrong, wrongRef, outside, cullWrong);
    RT_CHECK((accepted > 20000) && (refused > 20000) && (outside > 20000) && (outside < 180000), "the draws do not reach both answers (test setup)");
    RT_CHECK(wrong == 0 && wrongRef == 0, "billboard checks: %d four-lane answers differ from one at a time, %d from the reference", wrong, wrongRef);
    RT_CHECK(cullWrong == 0, "culling: %d four-lane answers differ from one at a time or the reference", cullWrong);
}
