// Instanced path specification: the vertex shader expands the same quads as the CPU path.
// Vertices are captured from the GPU with transform feedback and compared with
// RblBillboardVertices() (which the immediate and batched paths share). Included by test_gpu_main.c.

#include "tf_capture.h"
#include "degenerate.h"

static RblBillboard billboardOf(const RblInstance *in, RblInstancedDesc d)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = in->position; b.rotation = in->rotation; b.size = in->size; b.origin = in->origin;
    b.source = in->source; b.tint = in->tint; b.flags = in->flags;
    b.facing = d.facing; b.up = d.up; b.axis = d.axis; b.roundness = d.roundness;
    return b;
}

static RblInstance randomInstance(unsigned int *seed)
{
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.position = (Vector3){ rtRandomRange(seed, -20, 20), rtRandomRange(seed, -5, 5), rtRandomRange(seed, -20, 20) };
    in.rotation = (rtRandom(seed) & 1)? rtRandomRange(seed, -360, 360) : 0.0f;
    in.size = (Vector2){ rtRandomRange(seed, -4, 4), rtRandomRange(seed, -4, 4) };
    in.origin = (Vector2){ rtRandomRange(seed, -1, 2), rtRandomRange(seed, -1, 2) };
    in.source = (Rectangle){ rtRandomRange(seed, 0, 128), rtRandomRange(seed, 0, 128), rtRandomRange(seed, -128, 128), rtRandomRange(seed, -128, 128) };
    in.tint = (Color){ (unsigned char)rtRandom(seed), (unsigned char)rtRandom(seed), (unsigned char)rtRandom(seed), 255 };
    in.flags = rtRandom(seed) & 3;
    return in;
}

static void test_instanced_vertices_equal_the_cpu_path_in_every_mode(void)
{
    TfGl gl;
    RT_CHECK(tfLoad(&gl), "transform feedback entry points missing");
    GLu prog = tfProgram(&gl);
    RT_CHECK(prog != 0, "instanced vertex stage did not link with transform feedback");
    if (prog == 0) return;
    RblInstanceBuffer buf = RblLoadInstanceBuffer(256);
    Camera3D cam = makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.1f, 1.0f, 0.0f });
    unsigned int seed = 777u;
    const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
    double worstPos = 0.0, worstAttr = 0.0;
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    for (int variant = 0; variant < 2; variant++)
    {
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = facing;
        d.roundness = variant? 0.7f : 0.0f;
        if (variant && facing == RBL_FACING_CAMERA_PLANE) d.up = (Vector3){ 0.2f, 1.5f, 0.0f };
        if (variant && facing == RBL_FACING_AXIS) d.axis = (Vector3){ 0.3f, 1.0f, -0.2f };
        if (facing == RBL_FACING_FIXED) { d.axis = (Vector3){ 0.2f, 0.5f, 1.0f }; d.up = variant? (Vector3){ 1, 1, 0 } : (Vector3){ 0, 0, 0 }; }
        RblInstance in[256];
        for (int i = 0; i < 256; i++) in[i] = randomInstance(&seed);
        float *gpu = tfCapture(&gl, prog, &buf, cam, d, 256, 128, in, 256);
        RblCameraFrame view = RblGetCameraFrame(cam);
        for (int i = 0; i < 256; i++)
        {
            RblBillboard b = billboardOf(&in[i], d);
            RblVertex q[4];
            RT_CHECK(RblBillboardVertices(&view, 256, 128, &b, q), "cpu skipped instance %d", i);
            double scale = 1.0 + dLen(d3f(b.position)) + fabs(b.size.x) + fabs(b.size.y) + fabs(b.origin.x) + fabs(b.origin.y);
            for (int v = 0; v < 6; v++)
            {
                const float *g = gpu + ((size_t)i*6 + v)*TF_FLOATS;
                const RblVertex *c = &q[cornerOf[v]];
                for (int k = 0; k < 3; k++) worstPos = fmax(worstPos, fabs(g[k] - c->position[k])/scale);
                for (int k = 0; k < 2; k++) worstAttr = fmax(worstAttr, fabs(g[3 + k] - c->texcoord[k]));
                for (int k = 0; k < 3; k++) worstAttr = fmax(worstAttr, fabs(g[5 + k] - c->normal[k]));
                for (int k = 0; k < 4; k++) worstAttr = fmax(worstAttr, fabs(g[8 + k] - c->tangent[k]));
            }
        }
        free(gpu);
    }
    RT_CHECK(worstPos < 1e-5, "worst relative position difference instanced vs cpu %.3g", worstPos);
    RT_CHECK(worstAttr < 1e-5, "worst uv/normal/tangent difference instanced vs cpu %.3g", worstAttr);
    printf("    instanced vs cpu: worst relative position %.2e, worst attribute %.2e over 2048 billboards\n", worstPos, worstAttr);
    gl.DeleteProgram(prog);
    RblUnloadInstanceBuffer(&buf);
}

// Degenerate cameras and the eye on the billboard: the GPU frame stays finite and unit as well
static void test_instanced_hard_cases_stay_finite(void)
{
    TfGl gl;
    if (!tfLoad(&gl)) { RT_CHECK(false, "no GL entry points"); return; }
    GLu prog = tfProgram(&gl);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(8);
    Camera3D cams[3] = {
        makeCamera((Vector3){ 0, 10, 0 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 }),     // straight down, up parallel
        makeCamera((Vector3){ 0, -10, 0 }, (Vector3){ 0, 0, 0 }, (Vector3){ 0, 1, 0 }),    // straight up
        makeCamera((Vector3){ 1, 2, 3 }, (Vector3){ 1, 2, 3 }, (Vector3){ 0, 1, 0 }),      // target == position
    };
    for (int c = 0; c < 3; c++)
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    {
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = facing;
        RblInstance in[2];
        memset(in, 0, sizeof(in));
        in[0].size = (Vector2){ 1, 1 };
        in[1].size = (Vector2){ 0, 0 };
        in[1].position = cams[c].position;      // centre at the eye, zero size
        float *gpu = tfCapture(&gl, prog, &buf, cams[c], d, 4, 4, in, 2);
        for (int v = 0; v < 12; v++)
        {
            const float *g = gpu + v*TF_FLOATS;
            bool finite = true;
            for (int k = 0; k < TF_FLOATS; k++) finite = finite && rtFinite(g[k]);
            double nl = sqrt(g[5]*g[5] + g[6]*g[6] + g[7]*g[7]), tl = sqrt(g[8]*g[8] + g[9]*g[9] + g[10]*g[10]);
            double nt = g[5]*g[8] + g[6]*g[9] + g[7]*g[10];
            RT_CHECK(finite && fabs(nl - 1.0) < 1e-5 && fabs(tl - 1.0) < 1e-5 && fabs(nt) < 1e-5,
                     "camera %d mode %d vertex %d: finite %d |N| %.6f |T| %.6f N.T %.2g", c, facing, v, finite, nl, tl, nt);
        }
        free(gpu);
    }
    gl.DeleteProgram(prog);
    RblUnloadInstanceBuffer(&buf);
}

// One near-degenerate case through the instanced stage (6 captured vertices, freed by the caller)
static float *dgGpuCase(TfGl *gl, GLu prog, RblInstanceBuffer *buf, const DgCase *c)
{
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.position = c->billboard.position; in.size = c->billboard.size; in.origin = c->billboard.origin;
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.facing = c->billboard.facing; d.up = c->billboard.up; d.axis = c->billboard.axis; d.roundness = c->billboard.roundness;
    tfLight = c->light; tfMinCastSin = c->minSin;
    float *gpu = tfCapture(gl, prog, buf, c->camera, d, 64, 64, &in, 1);
    tfLight = (Vector4){ 0 }; tfMinCastSin = 0.0f;
    return gpu;
}

// Near-degenerate frames (tests/degenerate.h: every fallback approached from 5 degrees down to
// 1e-7 rad, both sides, six azimuths): the instanced stage emits the CPU path's vertices within 1e-5
// along every sweep, with and without rounded normals. Densely through each blend's cancelling point
// (the opposed side at weight 1/2, where any continuous blend turns its output around within a
// rounding error) the instanced frame stays finite and orthonormal; how far the two paths' roundings
// take them apart there is reported.
static void test_instanced_near_degenerate_frames_agree_with_the_cpu_path(void)
{
    TfGl gl;
    if (!tfLoad(&gl)) { RT_CHECK(false, "transform feedback entry points missing"); return; }
    GLu prog = tfProgram(&gl);
    RT_CHECK(prog != 0, "instanced vertex stage did not link with transform feedback");
    if (prog == 0) return;
    RblInstanceBuffer buf = RblLoadInstanceBuffer(4);
    const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
    double worstAll = 0.0;
    for (int config = 0; config < DG_CONFIGS; config++)
    {
        double worstPos = 0.0, worstAttr = 0.0, worstNT = 0.0, worstAngle = 0.0;
        for (int k = 0; k < DG_CASES; k++)
        {
            DgCase c = dgCase(config, k);
            c.billboard.roundness = (c.azimuth & 2)? 0.5f : 0.0f;
            RblVertex q[4];
            RT_CHECK(dgCpuQuad(&c, 64, 64, q), "%s case %d: cpu skipped", dgNames[config], k);
            float *gpu = dgGpuCase(&gl, prog, &buf, &c);
            double scale = 1.0 + dLen(d3f(c.billboard.position)) + 3.0;
            double casePos = 0.0, caseAttr = 0.0;
            for (int v = 0; v < 6; v++)
            {
                const float *g = gpu + (size_t)v*TF_FLOATS;
                const RblVertex *cv = &q[cornerOf[v]];
                for (int j = 0; j < 3; j++) casePos = fmax(casePos, fabs(g[j] - cv->position[j])/scale);
                for (int j = 0; j < 3; j++) caseAttr = fmax(caseAttr, fabs(g[5 + j] - cv->normal[j]));
                for (int j = 0; j < 4; j++) caseAttr = fmax(caseAttr, fabs(g[8 + j] - cv->tangent[j]));
                worstNT = fmax(worstNT, fabs(g[5]*g[8] + g[6]*g[9] + g[7]*g[10]));
            }
            if (fmax(casePos, caseAttr) > 1e-5 && fmax(worstPos, worstAttr) <= 1e-5)
                printf("    %s: first case over 1e-5: angle %.3g side %d variant %d azimuth %d (pos %.2e attr %.2e)\n",
                       dgNames[config], c.angle, c.side, c.variant, c.azimuth*60, casePos, caseAttr);
            if (fmax(casePos, caseAttr) > fmax(worstPos, worstAttr)) worstAngle = c.angle;
            worstPos = fmax(worstPos, casePos); worstAttr = fmax(worstAttr, caseAttr);
            free(gpu);
        }
        printf("    %-32s instanced vs cpu: position %.2e, attributes %.2e (worst at %.2g), gpu |N.T| %.2e\n", dgNames[config], worstPos, worstAttr, worstAngle, worstNT);
        worstAll = fmax(worstAll, fmax(worstPos, worstAttr));
        RT_CHECK(worstPos < 1e-5 && worstAttr < 1e-5, "%s: instanced vs cpu position %.3g attributes %.3g", dgNames[config], worstPos, worstAttr);
    }
    printf("    near-degenerate sweeps (%d cases): worst instanced vs cpu %.2e\n", DG_CASES*DG_CONFIGS, worstAll);
    // Through the cancelling points: the instanced frame alone
    double worstOrtho = 0.0, worstApart = 0.0;
    int apart = 0, dense = 0;
    for (int config = 0; config < DG_CONFIGS; config++)
    for (int k = 0; (dgCancelAngle(config) > 0.0) && (k < DG_DENSE_CASES); k++)
    {
        DgCase c = dgDenseCase(config, k);
        float *gpu = dgGpuCase(&gl, prog, &buf, &c);
        RblVertex q[4];
        dgCpuQuad(&c, 64, 64, q);
        D3 p0 = vecOf(gpu), e1 = dSub(vecOf(gpu + TF_FLOATS), p0), e2 = dSub(vecOf(gpu + 5*TF_FLOATS), p0);     // corners 1 and 3
        e1 = dScale(e1, 1.0/dLen(e1)); e2 = dScale(e2, 1.0/dLen(e2));
        bool parallelogram = (c.billboard.facing == RBL_FACING_CAMERA_PLANE) && (dDot(d3f(c.billboard.up), d3f(c.billboard.up)) > 1e-24);
        double o = 0.0, e = 0.0;
        for (int v = 0; v < 6; v++)
        {
            const float *g = gpu + (size_t)v*TF_FLOATS;
            D3 n = vecOf(g + 5), t = vecOf(g + 8);
            o = fmax(o, fmax(fabs(dLen(n) - 1.0), fmax(fabs(dLen(t) - 1.0), fabs(dDot(n, t)))));
            o = fmax(o, fmax(fabs(dDot(n, e1)), fabs(dDot(n, e2))));
            if (!parallelogram) o = fmax(o, fabs(dDot(e1, e2)));
            for (int j = 0; j < 3; j++) e = fmax(e, fabs(g[5 + j] - q[cornerOf[v]].normal[j]));
        }
        if (!(o <= worstOrtho)) worstOrtho = o;
        worstApart = fmax(worstApart, e);
        if (e > 1e-5) apart++;
        dense++;
        free(gpu);
    }
    RT_CHECK(worstOrtho <= 1e-5, "instanced frame through the cancelling points: orthonormality error %.3g", worstOrtho);
    printf("    through the cancelling points (%d cases within 2%% of the weight-1/2 angle): instanced orthonormality error %.2e; "
           "instanced vs cpu normals up to %.2e, %d cases over 1e-5\n", dense, worstOrtho, worstApart, apart);
    gl.DeleteProgram(prog);
    RblUnloadInstanceBuffer(&buf);
}

// Caller vectors too short to give a direction (|v| <= 1e-12 counts as zero: the default) and just
// long enough, including denormal lengths a GPU may flush to zero: both paths read them alike
static void test_instanced_tiny_up_and_axis_read_alike_on_cpu_and_gpu(void)
{
    TfGl gl;
    if (!tfLoad(&gl)) { RT_CHECK(false, "transform feedback entry points missing"); return; }
    GLu prog = tfProgram(&gl);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(4);
    Camera3D cam = makeCamera((Vector3){ 3.0f, 6.0f, 25.0f }, (Vector3){ -1.0f, 0.5f, 0.0f }, (Vector3){ 0.1f, 1.0f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    const float lengths[5] = { 1e-20f, 1e-13f, 9e-13f, 2e-12f, 1e-11f };
    const Vector3 dirs[3] = { { 1.0f, 0.0f, 0.0f }, { 0.0f, 0.6f, 0.8f }, { -0.48f, 0.6f, 0.64f } };
    const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
    double worst = 0.0;
    int cases = 0;
    for (int facing = RBL_FACING_CAMERA_PLANE; facing <= RBL_FACING_FIXED; facing++)
    for (int which = 0; which < 2; which++)          // 0: up tiny, 1: axis tiny
    for (int li = 0; li < 5; li++)
    for (int di = 0; di < 3; di++)
    {
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = facing;
        Vector3 v = { dirs[di].x*lengths[li], dirs[di].y*lengths[li], dirs[di].z*lengths[li] };
        if (which == 0) { d.up = v; if (facing == RBL_FACING_FIXED) d.axis = (Vector3){ 0.2f, 0.5f, 1.0f }; }
        else { d.axis = v; if (facing == RBL_FACING_FIXED) d.up = (Vector3){ 0.3f, 1.0f, 0.0f }; }
        RblInstance in;
        memset(&in, 0, sizeof(in));
        in.position = (Vector3){ 1.0f, 0.5f, -2.0f }; in.size = (Vector2){ 1.5f, 2.0f }; in.origin = (Vector2){ 0.75f, 0.5f };
        float *gpu = tfCapture(&gl, prog, &buf, cam, d, 8, 8, &in, 1);
        RblBillboard b = billboardOf(&in, d);
        RblVertex q[4];
        RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "cpu skipped");
        double e = 0.0;
        for (int k = 0; k < 6; k++)
        {
            const float *g = gpu + (size_t)k*TF_FLOATS;
            const RblVertex *c = &q[cornerOf[k]];
            for (int j = 0; j < 3; j++) e = fmax(e, fmax(fabs(g[j] - c->position[j])/4.0, fabs(g[5 + j] - c->normal[j])));
            for (int j = 0; j < 4; j++) e = fmax(e, fabs(g[8 + j] - c->tangent[j]));
        }
        RT_CHECK(e < 1e-5, "mode %d, %s of length %g along (%g, %g, %g): instanced vs cpu %.3g", facing, which? "axis" : "up", lengths[li], dirs[di].x, dirs[di].y, dirs[di].z, e);
        worst = fmax(worst, e);
        cases++;
        free(gpu);
    }
    printf("    tiny up/axis (lengths 1e-20 .. 1e-11, %d cases): worst instanced vs cpu %.2e\n", cases, worst);
    gl.DeleteProgram(prog);
    RblUnloadInstanceBuffer(&buf);
}

// Rotation at any angle an instance may carry (|value| < 2^120): the instanced stage's exact degree
// reduction (rblReduceDegrees, integer arithmetic) against the CPU's fmodf and a double reference.
// Seen from the front the tangent of an unflipped quad is (cos, sin, 0) of the rotation.
static void test_instanced_rotation_agrees_with_the_cpu_at_any_angle(void)
{
    TfGl gl;
    if (!tfLoad(&gl)) { RT_CHECK(false, "transform feedback entry points missing"); return; }
    GLu prog = tfProgram(&gl);
    enum { FIXED_ANGLES = 24, RANDOM_ANGLES = 1000, N = FIXED_ANGLES + RANDOM_ANGLES };
    static const float fixedAngles[FIXED_ANGLES] = {
        1e4f, -1e4f, 1e6f, -1e6f, 3.6e8f, -3.6e8f, 12345.678f, -98765.4321f, 1000000.3f, -7777777.7f, 368639.97f, 368640.03f,
        -368641.0f, 16777215.0f, -16777217.0f, 94371840.0f /* 90 x 2^20 */, 283115520.0f /* 270 x 2^20 */, 4.831838e10f /* 45 x 2^30 */,
        1e30f, -1e30f, 1.3e36f, -1.3e36f, 359.99997f, -0.00001f };
    RblInstance in[N];
    float angles[N];
    unsigned int seed = 90210u;
    for (int i = 0; i < N; i++)
    {
        // random: magnitude log-uniform over 1e-3 .. 1e36, either sign, fraction bits set wherever float has them
        float a = (i < FIXED_ANGLES)? fixedAngles[i] : (float)pow(10.0, rtRandomRange(&seed, -3.0f, 36.0f));
        if ((i >= FIXED_ANGLES) && (rtRandom(&seed) & 1)) a = -a;
        angles[i] = a;
        memset(&in[i], 0, sizeof(in[i]));
        in[i].position = (Vector3){ 0.25f*(float)(i%7), 0.5f*(float)(i%5), 0.0f };
        in[i].size = (Vector2){ 1.0f, 2.0f }; in[i].origin = (Vector2){ 0.5f, 0.25f };
        in[i].rotation = a;
    }
    RblInstanceBuffer buf = RblLoadInstanceBuffer(N);
    Camera3D cam = makeCamera((Vector3){ 0.0f, 0.0f, 10.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
    RblCameraFrame view = RblGetCameraFrame(cam);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    float *gpu = tfCapture(&gl, prog, &buf, cam, d, 8, 8, in, N);
    const int cornerOf[6] = { 0, 1, 2, 0, 2, 3 };
    double worstRef = 0.0, worstCpu = 0.0, worstCpuRef = 0.0;
    int exactQuadrants = 0, quadrantAngles = 0;
    for (int i = 0; i < N; i++)
    {
        double r = fmod((double)angles[i], 360.0)*(3.14159265358979323846/180.0), cr = cos(r), sr = sin(r);
        const float *g = gpu + (size_t)i*6*TF_FLOATS;
        double e = fmax(fabs(g[8] - cr), fabs(g[9] - sr));
        RT_CHECK(e <= 1e-6 && g[10] == 0.0f, "%.9g degrees: instanced (cos, sin) (%.9g, %.9g), double (%.9g, %.9g)", angles[i], g[8], g[9], cr, sr);
        worstRef = fmax(worstRef, e);
        if (fmod((double)angles[i], 90.0) == 0.0)
        {
            quadrantAngles++;
            if ((g[8] == (float)cr) && (g[9] == (float)sr)) exactQuadrants++;
        }
        RblBillboard b = billboardOf(&in[i], d);
        RblVertex q[4];
        RT_CHECK(RblBillboardVertices(&view, 8, 8, &b, q), "cpu skipped %g degrees", angles[i]);
        worstCpuRef = fmax(worstCpuRef, fmax(fabs(q[0].tangent[0] - cr), fabs(q[0].tangent[1] - sr)));
        for (int v = 0; v < 6; v++)
        {
            const float *gv = gpu + ((size_t)i*6 + v)*TF_FLOATS;
            const RblVertex *c = &q[cornerOf[v]];
            for (int k = 0; k < 3; k++) worstCpu = fmax(worstCpu, fmax(fabs(gv[k] - c->position[k])/4.0, fabs(gv[5 + k] - c->normal[k])));
            for (int k = 0; k < 4; k++) worstCpu = fmax(worstCpu, fabs(gv[8 + k] - c->tangent[k]));
        }
    }
    RT_CHECK(worstCpu < 1e-6, "instanced vs cpu at large angles: %.3g", worstCpu);
    RT_CHECK(worstCpuRef <= 1e-6, "cpu (cos, sin) vs double at large angles: %.3g", worstCpuRef);
    RT_CHECK(quadrantAngles >= 10 && exactQuadrants == quadrantAngles, "%d of %d multiples of 90 degrees exact on the instanced stage", exactQuadrants, quadrantAngles);
    printf("    rotation at %d angles up to 1.3e36 degrees: instanced vs double %.2e, cpu vs double %.2e, instanced vs cpu %.2e; %d multiples of 90 exact\n",
           N, worstRef, worstCpuRef, worstCpu, quadrantAngles);
    free(gpu);
    gl.DeleteProgram(prog);
    RblUnloadInstanceBuffer(&buf);
}

// RblDrawInstanced itself: skips bad instances with one warning, and renders what the batch renders
static void test_instanced_draw_matches_batched_pixels_and_skips_bad_instances(void)
{
    Camera3D cam = frontCamera();
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1;
    desc.material.normalEncoding = RBL_NORMAL_RGB;
    // View-dependent shading (GGX highlight, fog by eye distance): the instanced stage must hand the
    // fragment stage the same eye as matView gives the batched one
    desc.shading.brdf = RBL_BRDF_GGX;
    desc.shading.fog = RBL_FOG_EXP;
    Shader plain = RblLoadLitShader(desc);
    desc.instanced = true;
    Shader inst = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(plain) && RblIsLitShaderValid(inst), "lit variants failed");
    Texture2D albedo = solidTexture((Color){ 220, 200, 160, 255 }), nmap = solidTexture(normalTexel(0.5f, 0.3f, 0.81f));
    Material m = LoadMaterialDefault();
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = nmap;
    rtSetMaterialValues(&m, (RtMaterialValues){ .roughness = 0.3f });
    RblLight l = rtPointLight((Vector3){ 1.5f, 1.0f, 2.0f }, 5.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &l; scene.lightCount = 1;
    scene.ambient = (Color){ 25, 25, 25, 255 };
    scene.fog = (RblFog){ RBL_FOG_EXP, (Color){ 30, 40, 60, 255 }, 0.0f, 0.0f, 0.08f };
    RT_CHECK(RblSetScene(&scene), "scene rejected");

    unsigned int seed = 31u;
    RblInstance in[12];
    for (int i = 0; i < 12; i++)
    {
        memset(&in[i], 0, sizeof(in[i]));
        in[i].position = (Vector3){ rtRandomRange(&seed, -1.5f, 1.5f), rtRandomRange(&seed, -1.5f, 1.5f), -0.2f*i };
        in[i].size = (Vector2){ (i & 1)? -0.7f : 0.7f, 0.7f };
        in[i].origin = (Vector2){ 0.35f, 0.35f };
        in[i].rotation = 20.0f*i;
        in[i].flags = (i%3 == 0)? RBL_FRAME_ROTATED : 0;
    }
    in[3].position.x = NAN;
    in[7].size.y = INFINITY;
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.facing = RBL_FACING_CAMERA_POSITION;
    d.roundness = 0.5f;

    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(4);     // grows to 16 with one info line
    warnings = 0;
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    m.shader = inst;
    int drawn = RblDrawInstanced(&buf, cam, m, d, in, 12);
    EndMode3D(); EndTextureMode();
    RT_CHECK(drawn == 10 && buf.skipped == 2, "drawn %d skipped %d", drawn, buf.skipped);
    RT_CHECK(warnings == 1, "one warning for the skipped instances, got %d", warnings);
    Image a = rtReadTarget(rt);

    RblBatch batch = RblLoadBatch(16);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    m.shader = plain;
    RblBeginBatch(&batch, cam);
    for (int i = 0; i < 12; i++) { RblBillboard b = billboardOf(&in[i], d); RblBatchAdd(&batch, m, &b); }
    RblEndBatch(&batch);
    EndMode3D(); EndTextureMode();
    Image b = rtReadTarget(rt);
    int lit = 0, off = 0;
    for (int y = 0; y < TARGET; y++)
    for (int x = 0; x < TARGET; x++)
    {
        Color ca = rtPixel(a, x, y), cb = rtPixel(b, x, y);
        if (cb.r > 0) lit++;
        if (abs(ca.r - cb.r) > 1 || abs(ca.g - cb.g) > 1 || abs(ca.b - cb.b) > 1) off++;
    }
    RT_CHECK(lit > 300, "batched reference nearly empty (%d)", lit);
    RT_CHECK(off <= 4, "%d pixels differ by more than 1/255 between instanced and batched", off);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(a, "instanced"); rtSaveImage(b, "batched"); }

    // A non-instanced shader is refused with a warning, nothing drawn
    warnings = 0;
    RT_CHECK(RblDrawInstanced(&buf, cam, m, d, in, 2) == 0 && warnings == 1, "plain shader accepted for instancing");
    d.facing = 17;
    m.shader = inst;
    RT_CHECK(RblDrawInstanced(&buf, cam, m, d, in, 2) == 0, "bad facing accepted");

    UnloadImage(a); UnloadImage(b);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    RblUnloadInstanceBuffer(&buf);
    RblUnloadLitShader(&plain); RblUnloadLitShader(&inst);
    UnloadTexture(albedo); UnloadTexture(nmap);
    MemFree(m.maps);
}

// Where the context maps buffers, RblDrawInstanced (no fades, array order) checks each instance and
// copies it straight into the GPU buffer: the buffer then holds exactly what the checked upload
// uploads (read back, bit for bit), with the same return, skipped count, one log line, and the same
// back-face decision (pixels equal): sets of 1-203 instances with bad ones at every lane of a four
// (each float word NaN, Inf or 2^120, an unknown polygon handle), FIXED cards facing the camera or
// away (drawn only as backs), cards facing +x whose back only pivots late in the array see, in a
// colour and a shadow pass
static void test_instanced_mapped_upload_equals_the_checked_upload(void)
{
    enum { MAXN = 203 };
    static RblInstance set[MAXN];
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.instanced = true;
    Shader inst = RblLoadLitShader(desc);
    Material m = LoadMaterialDefault();
    m.shader = inst;
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(MAXN);
    Camera3D cam = frontCamera();
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ -0.4f, -1.0f, -0.3f }; sun.color = WHITE; sun.intensity = 1.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    RT_CHECK(RblSetScene(&scene), "scene rejected");
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    static unsigned char bytes[2][MAXN*sizeof(RblInstance)];
    const bool maps = (rbl__glsl() >= 300) && rbl__canMap();
    int cases = 0, equal = 0, skippedAll = 0;
    unsigned int seed = 404u;
    for (int c = 0; c < 40; c++)
    {
        const int n = (c < 8)? 1 + c : 1 + (int)(rtRandom(&seed)%MAXN);
        const bool shadow = (c % 10) == 9;
        RblInstancedDesc d;
        memset(&d, 0, sizeof(d));
        d.facing = (c % 3 == 0)? RBL_FACING_FIXED : RBL_FACING_CAMERA_POSITION;
        d.axis = (Vector3){ 0.3f, 0.2f, (c % 2)? 1.0f : -1.0f };         // FIXED: facing the camera or away (culled unless seen as backs)
        if (c % 6 == 3) d.axis = (Vector3){ 1.0f, 0.0f, 0.0f };         // facing +x: pivots right of the eye show their backs
        for (int i = 0; i < n; i++)
        {
            RblInstance in;
            memset(&in, 0, sizeof(in));
            in.position = (Vector3){ rtRandomRange(&seed, -1.5f, 1.5f), rtRandomRange(&seed, -1.5f, 1.5f), rtRandomRange(&seed, -1.0f, 1.0f) };
            // facing +x: the first half left of the eye (fronts), the rest anywhere
            if ((c % 6 == 3) && (i <= n/2)) in.position.x = rtRandomRange(&seed, -1.5f, -0.1f);
            in.rotation = rtRandomRange(&seed, -180.0f, 180.0f);
            in.size = (Vector2){ rtRandomRange(&seed, -0.6f, 0.6f), 0.5f };
            in.origin = (Vector2){ 0.2f, 0.25f };
            in.source = (Rectangle){ 0.0f, 0.0f, 1.0f, 1.0f };
            in.tint = (Color){ 200, (unsigned char)rtRandom(&seed), 150, 255 };
            in.flags = rtRandom(&seed) & (RBL_FRAME_ROTATED | RBL_ROUND_CYLINDER | 12u);
            unsigned int bad = rtRandom(&seed)%40u;
            if (bad < 12)
            {
                float v = (bad % 3 == 0)? NAN : (bad % 3 == 1)? -INFINITY : 1.329228e36f;      // 2^120
                memcpy((unsigned char *)&in + 4u*bad, &v, sizeof(v));
            }
            else if (bad == 12) in.flags |= 0x20u;        // a polygon handle no atlas has
            set[i] = in;
        }
        int drawn[2] = { 0, 0 }, skipped[2] = { 0, 0 }, lines[2] = { 0, 0 };
        Image img[2] = { { 0 }, { 0 } };
        bool read[2] = { false, false };
        for (int v = 0; v < 2; v++)
        {
            rbl__state.instanceNoMap = (v == 1);
            int before = warnings;
            if (shadow)
            {
                if (RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 3.0f))
                {
                    drawn[v] = RblDrawInstanced(&buf, cam, m, d, set, n);
                    RblEndShadowMap(&map);
                }
            }
            else
            {
                BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
                drawn[v] = RblDrawInstanced(&buf, cam, m, d, set, n);
                EndMode3D(); EndTextureMode();
                img[v] = rtReadTarget(rt);
            }
            skipped[v] = buf.skipped; lines[v] = warnings - before;
            rbl__InstanceBufferState *st = rbl__instanceState(&buf);
            const void *p = (maps && (st != NULL) && (drawn[v] > 0))? rbl__mapBuffer(st->vboId, (size_t)drawn[v]*sizeof(RblInstance), true) : NULL;
            if (p != NULL) { memcpy(bytes[v], p, (size_t)drawn[v]*sizeof(RblInstance)); read[v] = rbl__unmapBuffer(st->vboId); }
        }
        rbl__state.instanceNoMap = false;
        int differ = 0;
        for (int i = 0; !shadow && (i < TARGET*TARGET); i++)
        {
            Color a = ((const Color *)img[0].data)[i], b = ((const Color *)img[1].data)[i];
            differ += (a.r != b.r) || (a.g != b.g) || (a.b != b.b) || (a.a != b.a);
        }
        bool same = (drawn[0] == drawn[1]) && (skipped[0] == skipped[1]) && (drawn[0] + skipped[0] == n) && (differ == 0) &&
                    (!maps || (read[0] && read[1] && (memcmp(bytes[0], bytes[1], (size_t)drawn[0]*sizeof(RblInstance)) == 0)));
        RT_CHECK(same, "case %d (%d instances%s): drawn %d / %d, skipped %d / %d, %d pixels differ, read back %d %d", c, n, shadow? ", shadow pass" : "",
                 drawn[0], drawn[1], skipped[0], skipped[1], differ, read[0], read[1]);
        RT_CHECK(lines[0] == lines[1] && lines[0] == ((skipped[0] > 0)? 1 : 0), "case %d: %d and %d log lines for %d skipped", c, lines[0], lines[1], skipped[0]);
        cases++; equal += same; skippedAll += skipped[0];
        if (!same && !shadow) { rtSaveImage(img[0], "mapped"); rtSaveImage(img[1], "checked"); }
        if (!shadow) { UnloadImage(img[0]); UnloadImage(img[1]); }
    }
    printf("    %d of %d draws equal (%s; %d instances skipped in all)\n", equal, cases, maps? "GPU buffers read back" : "no mapping here: both upload", skippedAll);
    RT_CHECK(skippedAll > 50, "the sets must hold bad instances (%d skipped)", skippedAll);
    RblUnloadShadowMap(&map);
    RblUnloadInstanceBuffer(&buf);
    UnloadRenderTexture(rt);
    RblUnloadLitShader(&inst);
    MemFree(m.maps);
}

// The instance check rejects exactly NaN, Inf and |value| >= 2^120 in each of the 12 float fields
// (values the GPU could overflow when it combines them), and nothing in the tint or flags
static void test_instanced_validation_bound_is_2_to_the_120_in_every_float_field(void)
{
    const float below = nextafterf(ldexpf(1.0f, 120), 0.0f), limit = ldexpf(1.0f, 120);
    const float rejected[4] = { limit, -limit, NAN, -INFINITY };
    const float accepted[4] = { below, -below, 1e-45f /* denormal */, -0.0f };
    int wrong = 0;
    for (int f = 0; f < 12; f++)
    {
        for (int k = 0; k < 4; k++)
        {
            RblInstance in;
            memset(&in, 0, sizeof(in));
            memcpy((unsigned char *)&in + offsetof(RblInstance, position) + (size_t)f*sizeof(float), &rejected[k], sizeof(float));
            if (rbl__instanceOk(&in)) wrong++;
            memset(&in, 0, sizeof(in));
            memcpy((unsigned char *)&in + offsetof(RblInstance, position) + (size_t)f*sizeof(float), &accepted[k], sizeof(float));
            if (!rbl__instanceOk(&in)) wrong++;
        }
    }
    RblInstance in;
    memset(&in, 0xFF, sizeof(in));     // NaN everywhere ...
    memset(&in, 0, offsetof(RblInstance, tint));     // ... except the floats: tint and flags are not checked
    RT_CHECK(rbl__instanceOk(&in), "tint/flags bits were read as floats");
    RT_CHECK(offsetof(RblInstance, tint) == 12*sizeof(float), "RblInstance floats are not the first 12 fields");
    RT_CHECK(wrong == 0, "%d of 96 field/value probes classified wrongly", wrong);
}

// Live registry entries (the header's one program registry) holding program id; the last one's
// rblInstancing location goes to *instancingLoc when given
static int instancedRegistryEntries(unsigned int id, int *instancingLoc)
{
    int n = 0;
    for (int i = 0; i < rbl__state.programCount; i++)
    {
        const rbl__Program *p = rbl__state.programs[i];
        if (p->shader.id == id) { n++; if (instancingLoc != NULL) *instancingLoc = p->loc[RBL__U_INSTANCING]; }
    }
    return n;
}

// GL hands a deleted program's id to the next program: the rblInstancing location RblDrawInstanced
// uses lives in the header's program registry, whose entry goes with the program's last holder and is
// looked up by id at each draw, so a variant given a reused id never draws with its predecessor's
// location (the instance buffer keeps none)
static void test_instanced_location_cache_survives_program_id_reuse(void)
{
    Camera3D cam = frontCamera();
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.instanced = true;
    desc.maxLights = 1;
    Shader a = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(a), "instanced variant failed");
    Material m = LoadMaterialDefault();
    RblInstanceBuffer buf = RblLoadInstanceBuffer(4);
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.size = (Vector2){ 2.0f, 2.0f };
    in.origin = (Vector2){ 1.0f, 1.0f };
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    RblLight l = rtPointLight((Vector3){ 0.5f, 0.5f, 3.0f }, 6.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &l; scene.lightCount = 1;
    scene.ambient = (Color){ 40, 40, 40, 255 };
    scene.fog = (RblFog){ RBL_FOG_EXP, (Color){ 30, 40, 60, 255 }, 0.0f, 0.0f, 0.1f };
    RT_CHECK(RblSetScene(&scene), "scene rejected");
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    m.shader = a;
    int drawnA = RblDrawInstanced(&buf, cam, m, d, &in, 1);
    EndMode3D(); EndTextureMode();
    unsigned int idA = a.id;
    int locA = -2;
    RT_CHECK(instancedRegistryEntries(idA, &locA) == 1, "program %u: %d registry entries, want 1", idA, instancedRegistryEntries(idA, NULL));
    RT_CHECK((locA != -1) && (locA == rlGetLocationUniform(idA, "rblInstancing")), "registry location %d for A, the program's is %d", locA, rlGetLocationUniform(idA, "rblInstancing"));
    RblUnloadLitShader(&a);
    RT_CHECK(a.id == 0, "RblUnloadLitShader did not zero the holder");
    // The last holder is gone: nothing in the registry may still answer for idA
    RT_CHECK(instancedRegistryEntries(idA, NULL) == 0, "unloaded program %u still has %d registry entries", idA, instancedRegistryEntries(idA, NULL));
    // A different variant (more uniforms ahead of rblInstancing), possibly given idA again by GL
    desc.maxLights = 8;
    desc.shading.brdf = RBL_BRDF_GGX;
    desc.shading.fog = RBL_FOG_EXP;
    Shader b = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(b), "second instanced variant failed");
    int fresh = rlGetLocationUniform(b.id, "rblInstancing");
    int locB = -2;
    RT_CHECK(instancedRegistryEntries(b.id, &locB) == 1, "program %u: %d registry entries, want 1", b.id, instancedRegistryEntries(b.id, NULL));
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    m.shader = b;
    int drawnB = RblDrawInstanced(&buf, cam, m, d, &in, 1);
    EndMode3D(); EndTextureMode();
    Image gotB = rtReadTarget(rt);
    printf("    program id %s reused by GL (%u -> %u); registry location %d, fresh lookup %d (A's was %d)\n",
           (b.id == idA)? "was" : "was not", idA, b.id, locB, fresh, locA);
    RT_CHECK((drawnA == 1) && (drawnB == 1), "drawn %d then %d", drawnA, drawnB);
    RT_CHECK((fresh != -1) && (locB == fresh), "registry rblInstancing location %d, the program's is %d", locB, fresh);
    // And the draw itself used B's location: it renders what B's batched twin renders
    desc.instanced = false;
    Shader plainB = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(plainB), "batched twin failed");
    RblBatch batch = RblLoadBatch(1);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    m.shader = plainB;
    RblBeginBatch(&batch, cam);
    RblBillboard bb = billboardOf(&in, d);
    RblBatchAdd(&batch, m, &bb);
    RblEndBatch(&batch);
    EndMode3D(); EndTextureMode();
    Image refB = rtReadTarget(rt);
    int lit = 0, off = 0;
    for (int y = 0; y < TARGET; y++)
    for (int x = 0; x < TARGET; x++)
    {
        Color ca = rtPixel(gotB, x, y), cb = rtPixel(refB, x, y);
        if (cb.r > 0) lit++;
        if (abs(ca.r - cb.r) > 1 || abs(ca.g - cb.g) > 1 || abs(ca.b - cb.b) > 1) off++;
    }
    RT_CHECK(lit > 300, "batched reference nearly empty (%d)", lit);
    RT_CHECK(off <= 4, "%d pixels differ by more than 1/255 between B instanced and batched", off);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(gotB, "instanced"); rtSaveImage(refB, "batched"); }
    UnloadImage(gotB); UnloadImage(refB);
    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    RblUnloadInstanceBuffer(&buf);
    RblUnloadLitShader(&b); RblUnloadLitShader(&plainB);
    m.shader = (Shader){ 0 };
    MemFree(m.maps);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_INSTANCED_TESTS \
    RT_TEST_GLSL3(test_instanced_vertices_equal_the_cpu_path_in_every_mode), \
    RT_TEST_GLSL3(test_instanced_hard_cases_stay_finite), \
    RT_TEST_GLSL3(test_instanced_near_degenerate_frames_agree_with_the_cpu_path), \
    RT_TEST_GLSL3(test_instanced_tiny_up_and_axis_read_alike_on_cpu_and_gpu), \
    RT_TEST_GLSL3(test_instanced_rotation_agrees_with_the_cpu_at_any_angle), \
    RT_TEST_GLSL3(test_instanced_draw_matches_batched_pixels_and_skips_bad_instances), \
    RT_TEST_GLSL3(test_instanced_validation_bound_is_2_to_the_120_in_every_float_field), \
    RT_TEST_GLSL3(test_instanced_mapped_upload_equals_the_checked_upload), \
    RT_TEST_GLSL3(test_instanced_location_cache_survives_program_id_reuse)
