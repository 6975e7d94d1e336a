// Point-light (omni) shadows and cascaded directional shadows (GPU, headless). Included by
// gpu_tests.h after test_self_shadow.c (uses its rig: ssFloor, ssTopCamera, SS_*).
//   omni      the six cube faces of one casters target against a double-precision ray cast per
//             texel; the receivers' lookup against a double-precision CPU lookup of the same map
//             (face choice, projection, tile), two omni lights in one scene, forward and deferred
//   cascades  the practical split and each cascade's sphere against the slice corners (double);
//             shadow edges on a fixed floor while the camera pans and turns (snapped: no motion);
//             the blend band; texel size at 5 and 50 units against one map of equal memory

// Documented omni layout (rbillboard_lit.h SHADOWS): faces +X -X +Y / -Y +Z -Z in 3 x 2 tiles, up +Z
// for the Y faces and +Y otherwise, right = axis x up, each face a 90-degree perspective widened so
// that RBL_SHADOW_MAX_FILTER/2 + 2 texels each side lie beyond it
static void omFace(int f, double axis[3], double up[3], double right[3])
{
    double s = (f & 1)? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) { axis[k] = (f/2 == k)? s : 0.0; up[k] = 0.0; }
    if (f/2 == 1) up[2] = 1.0; else up[1] = 1.0;
    right[0] = axis[1]*up[2] - axis[2]*up[1]; right[1] = axis[2]*up[0] - axis[0]*up[2]; right[2] = axis[0]*up[1] - axis[1]*up[0];
}

static double omLinear(int c) { double x = c/255.0; return (x <= 0.04045)? x/12.92 : pow((x + 0.055)/1.055, 2.4); }

static double omTan(int size) { return (double)size/(size - 2.0*(RBL_SHADOW_MAX_FILTER/2 + 2)); }

// The casters target of a map as RGBA8 rows, bottom row first (GL's texel order)
static unsigned char *omReadCasters(const RblShadowMap *map)
{
    return (unsigned char *)rlReadTexturePixels(map->casters.id, map->casters.width, map->casters.height, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
}

// CPU lookup in double for a point of the floor y = 0: the face of the point's major axis from the
// light, its texel, the stored distance (the code's log scale) against the floor's own distance
// along that texel's ray (the receiver's plane at each texel, as the GPU's receiver-plane bias).
// Returns 1 shadowed, 0 lit, -1 undecided (a texel of the 5 x 5 block around it disagrees: the PCF
// footprint and the normal offset reach that far)
static int omCpuLookup(const unsigned char *texels, const RblShadowMap *map, Vector3 light, const double p[3])
{
    double d[3] = { p[0] - light.x, p[1] - light.y, p[2] - light.z };
    double a[3] = { fabs(d[0]), fabs(d[1]), fabs(d[2]) };
    int major = (a[0] >= a[1] && a[0] >= a[2])? 0 : ((a[1] >= a[2])? 1 : 2);
    int f = major*2 + ((d[major] < 0.0)? 1 : 0);
    double axis[3], up[3], right[3];
    omFace(f, axis, up, right);
    int size = map->size;
    double t = omTan(size), dist = d[0]*axis[0] + d[1]*axis[1] + d[2]*axis[2];
    (void)p;
    double u = 0.5 + 0.5*(d[0]*right[0] + d[1]*right[1] + d[2]*right[2])/(dist*t), v = 0.5 + 0.5*(d[0]*up[0] + d[1]*up[1] + d[2]*up[2])/(dist*t);
    int ti = (int)floor(u*size), tj = (int)floor(v*size), ox = (f%3)*size, oy = (f/3)*size, W = 3*size;
    double nearP = map->state->nearPlane, farP = map->state->farPlane;
    int verdict = -2;
    for (int j = -2; j <= 2; j++)
        for (int i = -2; i <= 2; i++)
        {
            int x = ti + i, y = tj + j;
            if ((x < 0) || (y < 0) || (x >= size) || (y >= size)) return -1;
            const unsigned char *q = texels + 4*((size_t)(oy + y)*W + ox + x);
            double code = (q[0]*256.0 + q[1])/65535.0, stored = nearP*exp(code*log(farP/nearP));
            double xn = ((x + 0.5)/size*2.0 - 1.0)*t, yn = ((y + 0.5)/size*2.0 - 1.0)*t;
            double dy = axis[1] + right[1]*xn + up[1]*yn, floorAt = (dy < -1e-9)? -light.y/dy : 1e30;
            int shadowed = (code < 1.0) && (stored < floorAt*0.98);
            if (verdict == -2) verdict = shadowed;
            else if (verdict != shadowed) return -1;
        }
    return verdict;
}

static void test_shadows_omni_cube_faces_hold_the_double_precision_distances(void)
{
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 64; sd.omni = true;
    RblShadowMap map = RblLoadShadowMap(sd);
    RT_CHECK(RblIsShadowMapValid(map) && (RblShadowMapPasses(map) == 6), "omni map failed to load or does not take six passes");
    RT_CHECK((map.casters.width == 3*64) && (map.casters.height == 2*64), "omni casters target %dx%d (expected 192x128: 3 x 2 faces)", map.casters.width, map.casters.height);
    Texture2D white = solidTexture(WHITE);
    Material m = LoadMaterialDefault();
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    Camera3D viewer = ssViewer();
    const Vector3 lights[3] = { { 0.3f, 1.5f, -0.2f }, { -2.0f, 0.4f, 1.0f }, { 0.0f, 6.0f, 0.0f } };
    int checked = 0, empty = 0, wrong = 0, worst = 0, faces[6] = { 0 };
    for (int li = 0; li < 3; li++)
    {
        RblLight light = litPoint(lights[li], 1.0f, 10.0f);
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = &light; scene.lightCount = 1;
        for (int pass = 0; pass < 6; pass++)
        {
            RT_CHECK(RblBeginShadowMapPass(&map, &scene, 0, pass, (Vector3){ 0 }, 0.0f), "face %d refused", pass);
            RblDrawBillboard(viewer, m, ssFloor());
            RblEndShadowMap(&map);
        }
        unsigned char *texels = omReadCasters(&map);
        RT_CHECK(texels != NULL, "casters target unreadable");
        double nearP = map.state->nearPlane, farP = map.state->farPlane, t = omTan(64);
        RT_CHECK(fabs(farP - 10.0) < 1e-5 && fabs(nearP - 0.01) < 1e-7, "near/far %g/%g (expected the range and range/1000)", nearP, farP);
        for (int f = 0; f < 6; f++)
        {
            double axis[3], up[3], right[3];
            omFace(f, axis, up, right);
            for (int j = 0; j < 64; j++)
                for (int i = 0; i < 64; i++)
                {
                    double x = ((i + 0.5)/64.0*2.0 - 1.0)*t, y = ((j + 0.5)/64.0*2.0 - 1.0)*t;
                    double dir[3] = { axis[0] + right[0]*x + up[0]*y, axis[1] + right[1]*x + up[1]*y, axis[2] + right[2]*x + up[2]*y };
                    const unsigned char *q = texels + 4*((size_t)((f/3)*64 + j)*192 + (f%3)*64 + i);
                    int code = q[0]*256 + q[1];
                    // The floor y = 0 over [-20, 20]^2: distance along the face's axis is the ray parameter
                    double s = (dir[1] < -1e-9)? -lights[li].y/dir[1] : 1e30;
                    double hx = lights[li].x + s*dir[0], hz = lights[li].z + s*dir[2];
                    bool hit = (s < 1e29) && (fabs(hx) < 20.0) && (fabs(hz) < 20.0) && (s < farP) && (s > nearP);
                    // Texels whose centre lies within a hair of the floor's edge or the far plane: not judged
                    if ((s < 1e29) && ((fabs(fabs(hx) - 20.0) < 0.05) || (fabs(fabs(hz) - 20.0) < 0.05) || (fabs(s - farP) < 0.01*farP))) continue;
                    if (!hit) { empty++; if (code != 65535) wrong++; continue; }
                    double expect = log(s/nearP)/log(farP/nearP)*65535.0;
                    int e = (int)fabs(code - floor(expect + 0.5));
                    if (e > worst) worst = e;
                    if (e > 1) wrong++;
                    checked++; faces[f]++;
                }
        }
        RL_FREE(texels);
    }
    printf("    omni 3 x 2 faces of 64, 3 light positions: %d texels on the floor (per face %d %d %d %d %d %d), worst %d of 65535 code steps from the double ray; %d empty texels\n",
           checked, faces[0], faces[1], faces[2], faces[3], faces[4], faces[5], worst, empty);
    RT_CHECK(wrong == 0, "omni faces: %d texels differ from the double-precision ray (worst %d code steps)", wrong, worst);
    for (int f = 0; f < 6; f++) if (f != 2) RT_CHECK(faces[f] > 100, "face %d: only %d floor texels (layout?)", f, faces[f]);
    MemFree(m.maps);
    UnloadTexture(white);
    RblUnloadShadowMap(&map);
}

// Two point lights, each with its omni map, over a floor with cut-out cards straddling the cube
// seams (beside the light, below it, at a corner of three faces) and a shuffled pair of sprites.
// Seen from above, every floor pixel the CPU's double lookup of the GPU's own maps calls clearly
// shadowed (its 5 x 5 texel block agrees) is darker than without maps, and every one it calls
// clearly lit is within 2/255; per map alone and with both. Deferred agrees with forward.
#define OM_VIEW 96
#define OM_WINDOW 8.0f
static void omDrawOccluders(Camera3D viewer, Material m, const Vector3 *lights)
{
    RblDrawBillboard(viewer, m, ssFloor());
    // Horizontal cards around each light: across the -Y/-X seam, at the -Y/+X/+Z corner, beside it
    const double offsets[4][3] = { { -0.5, -0.5, 0.0 }, { 0.5, -0.5, 0.5 }, { 0.0, -0.55, -0.55 }, { -0.9, -0.45, 0.8 } };
    for (int l = 0; l < 2; l++)
        for (int k = 0; k < 4; k++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.size = (Vector2){ 0.4f, 0.4f }; b.origin = (Vector2){ 0.2f, 0.2f };
            b.position = (Vector3){ lights[l].x + (float)offsets[k][0], lights[l].y + (float)offsets[k][1], lights[l].z + (float)offsets[k][2] };
            b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; b.up = (Vector3){ 0.0f, 0.0f, -1.0f };
            RblDrawBillboard(viewer, m, b);
        }
}

static Camera3D omTop(void)
{
    Camera3D c = ssTopCamera();
    c.fovy = OM_WINDOW;
    return c;
}

// The floor rig of the omni tests: a white material on a lit program receiving shadowMaps maps of
// the given lights, an OM_VIEW target and the scene seen from above (ambient 30)
typedef struct OmRig { Shader lit; Texture2D white; Material m; RenderTexture2D target; Camera3D top; RblScene scene; } OmRig;

static OmRig omRigLoad(RblLight *lights, int count, int shadowMaps)
{
    OmRig r;
    memset(&r, 0, sizeof(r));
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = count; desc.shading.lightFeatures = RblGetLightFeatures(lights, count); desc.shading.shadowMaps = shadowMaps;
    r.lit = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(r.lit), "lit program failed to load");
    r.white = solidTexture(WHITE);
    r.m = LoadMaterialDefault();
    r.m.shader = r.lit;
    r.m.maps[MATERIAL_MAP_ALBEDO].texture = r.white;
    r.target = LoadRenderTexture(OM_VIEW, OM_VIEW);
    r.top = omTop();
    r.scene.lights = lights; r.scene.lightCount = count; r.scene.ambient = (Color){ 30, 30, 30, 255 };
    return r;
}

// The floor drawn forward under the rig's scene as it stands, read back
static Image omForwardFloor(OmRig *r)
{
    RT_CHECK(RblSetScene(&r->scene), "scene rejected");
    BeginTextureMode(r->target);
    ClearBackground(BLACK);
    BeginMode3D(r->top);
    RblDrawBillboard(r->top, r->m, ssFloor());
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(r->target);
}

static void omRigUnload(OmRig *r)
{
    UnloadRenderTexture(r->target);
    MemFree(r->m.maps);
    UnloadTexture(r->white);
    RblUnloadLitShader(&r->lit);
}

// The floor drawn through a G-buffer of OM_VIEW pixels receiving the scene's two maps, resolved
// into target (a failed G-buffer or geometry variant is a failed check and a blank image)
static Image omDeferredFloor(int lightFeatures, const RblScene *scene, Material m, Camera3D top, RenderTexture2D target)
{
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = OM_VIEW; gd.height = OM_VIEW; gd.shading.lightFeatures = lightFeatures; gd.shading.shadowMaps = 2;
    RblGBuffer g = RblLoadGBuffer(gd);
    RblLitShaderDesc ld;
    memset(&ld, 0, sizeof(ld));
    ld.deferred = true;
    Shader geo = RblLoadLitShader(ld);
    Image def = GenImageColor(OM_VIEW, OM_VIEW, BLANK);
    if (RblIsGBufferValid(g) && RblIsLitShaderValid(geo))
    {
        RT_CHECK(RblSetScene(scene), "scene rejected");
        Material dm = m;
        dm.shader = geo;
        if (RblBeginGBuffer(&g, top))
        {
            RblDrawBillboard(top, dm, ssFloor());
            RblEndGBuffer(&g);
            RblDrawDeferredLights(&g);
        }
        BeginTextureMode(target);
        ClearBackground(BLACK);
        RblResolveGBuffer(&g);
        EndTextureMode();
        UnloadImage(def);
        def = rtReadTarget(target);
    }
    else RT_CHECK(false, "G-buffer or geometry variant failed to load");
    RblUnloadLitShader(&geo);
    RblUnloadGBuffer(&g);
    return def;
}

// Largest channel difference of two OM_VIEW images, and where
static int omWorstChannel(Image a, Image b, int *wx, int *wy)
{
    int worst = 0;
    for (int y = 0; y < OM_VIEW; y++)
        for (int x = 0; x < OM_VIEW; x++)
        {
            Color p = rtPixel(a, x, y), q = rtPixel(b, x, y);
            int d = abs((int)p.r - q.r);
            if (abs((int)p.g - q.g) > d) d = abs((int)p.g - q.g);
            if (abs((int)p.b - q.b) > d) d = abs((int)p.b - q.b);
            if (d > worst) { worst = d; *wx = x; *wy = y; }
        }
    return worst;
}

static void test_shadows_two_omni_lights_match_a_double_precision_lookup_forward_and_deferred(void)
{
    const Vector3 lpos[2] = { { -1.6f, 1.0f, 0.4f }, { 1.7f, 1.3f, -0.6f } };
    RblLight lights[2] = { litPoint(lpos[0], 0.8f, 12.0f), litPoint(lpos[1], 0.8f, 12.0f) };
    lights[0].color = lights[1].color = WHITE;
    OmRig rig = omRigLoad(lights, 2, 2);
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 256; sd.omni = true;
    RblShadowMap maps[2] = { RblLoadShadowMap(sd), RblLoadShadowMap(sd) };
    RT_CHECK(RblIsShadowMapValid(maps[0]) && RblIsShadowMapValid(maps[1]), "maps failed to load");
    Material m = rig.m;
    Camera3D top = rig.top;
    RblScene *scene = &rig.scene;
    for (int l = 0; l < 2; l++)
        for (int pass = 0; pass < RblShadowMapPasses(maps[l]); pass++)
        {
            RT_CHECK(RblBeginShadowMapPass(&maps[l], scene, l, pass, (Vector3){ 0 }, 0.0f), "light %d face %d refused", l, pass);
            omDrawOccluders(top, m, lpos);
            RblEndShadowMap(&maps[l]);
        }
    unsigned char *texels[2] = { omReadCasters(&maps[0]), omReadCasters(&maps[1]) };
    // Four renders: no map, map 0 alone, map 1 alone, both (the floor only: occluders cast, are not
    // seen); then each light alone without maps (how much it adds at each pixel)
    Image img[6];
    for (int k = 0; k < 6; k++)
    {
        RblShadowMap list[2];
        int n = 0;
        if ((k < 4) && (k & 1)) list[n++] = maps[0];
        if ((k < 4) && (k & 2)) list[n++] = maps[1];
        scene->shadowMaps = list; scene->shadowMapCount = n;
        scene->lights = (k == 5)? &lights[1] : lights; scene->lightCount = (k < 4)? 2 : 1;
        img[k] = omForwardFloor(&rig);
    }
    int judged[4] = { 0 }, wrong[4] = { 0 }, dark[4] = { 0 }, undecided = 0, seam = 0;
    for (int y = 0; y < OM_VIEW; y++)
        for (int x = 0; x < OM_VIEW; x++)
        {
            float px = OM_WINDOW/OM_VIEW;
            double p[3] = { (x + 0.5)*px - OM_WINDOW*0.5, 0.0, (y + 0.5)*px - OM_WINDOW*0.5 };
            int s0 = omCpuLookup(texels[0], &maps[0], lpos[0], p), s1 = omCpuLookup(texels[1], &maps[1], lpos[1], p);
            // How far the point lies from a cube seam of either light (|major| - |second| along the axes)
            for (int l = 0; l < 2; l++)
            {
                double d[3] = { fabs(p[0] - lpos[l].x), fabs(p[1] - lpos[l].y), fabs(p[2] - lpos[l].z) };
                double hi = fmax(d[0], fmax(d[1], d[2])), lo = (d[0] + d[1] + d[2]) - hi - fmin(d[0], fmin(d[1], d[2]));
                if ((hi - lo < 0.1) && (s0 >= 0) && (s1 >= 0) && (s0 || s1)) seam++;
            }
            // A light adding less than 24/255 here (far, grazing) darkens too little to tell
            int u = rtPixel(img[0], x, y).r, amb = 30, add0 = rtPixel(img[4], x, y).r - amb, add1 = rtPixel(img[5], x, y).r - amb;
            for (int k = 1; k < 4; k++)
            {
                int a = (k & 1)? s0 : 0, b = (k & 2)? s1 : 0;
                if ((a < 0) || (b < 0)) { undecided++; continue; }
                if ((a && (add0 < 24)) || (b && (add1 < 24))) continue;
                int v = rtPixel(img[k], x, y).r;
                judged[k]++;
                // Shadowed: at least half of each shadowing light's share gone (in linear light: the
                // sRGB output compresses a dim light's share on top of a bright one)
                double drop = (a? omLinear(add0 + amb) - omLinear(amb) : 0.0) + (b? omLinear(add1 + amb) - omLinear(amb) : 0.0);
                bool bad = (a || b)? (omLinear(v) > omLinear(u) - 0.5*drop) : (abs(v - u) > 2);
                dark[k] += (a || b);
                if (bad && (wrong[k]++ < 3)) printf("      render %d pixel (%d, %d) = floor (%.2f, %.2f): lookup %d %d, unshadowed %d, rendered %d, lights add %d %d\n", k, x, y, p[0], p[2], s0, s1, u, v, add0, add1);
            }
        }
    printf("    two omni lights (256-texel faces): map 0 alone %d judged (%d shadowed), map 1 alone %d (%d), both %d (%d); %d undecided (PCF band); %d shadowed pixels within 0.1 of a cube seam; wrong %d %d %d\n",
           judged[1], dark[1], judged[2], dark[2], judged[3], dark[3], undecided, seam, wrong[1], wrong[2], wrong[3]);
    for (int k = 1; k < 4; k++)
    {
        RT_CHECK(dark[k] > 100, "render %d: only %d pixels clearly shadowed (test setup)", k, dark[k]);
        RT_CHECK(wrong[k] == 0, "render %d (maps %s): %d of %d floor pixels disagree with the double-precision lookup", k, (k == 3)? "both" : ((k == 1)? "0" : "1"), wrong[k], judged[k]);
    }
    RT_CHECK(seam > 20, "only %d shadowed pixels near a cube seam (test setup)", seam);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(img[3], "omni-both"); rtSaveImage(img[0], "omni-none"); }

    // Deferred: the same floor through a G-buffer receiving both maps
    if (rbl__glsl() >= 300)
    {
        scene->shadowMaps = maps; scene->shadowMapCount = 2; scene->lights = lights; scene->lightCount = 2;
        Image def = omDeferredFloor(RblGetLightFeatures(lights, 2), scene, m, top, rig.target);
        int wx = 0, wy = 0, worst = omWorstChannel(def, img[3], &wx, &wy);
        printf("    deferred vs forward, two omni maps: worst %d/255 over %d pixels (at %d, %d: deferred %d, forward %d, unshadowed %d)\n", worst, OM_VIEW*OM_VIEW,
               wx, wy, rtPixel(def, wx, wy).r, rtPixel(img[3], wx, wy).r, rtPixel(img[0], wx, wy).r);
        RT_CHECK(worst <= 2, "deferred vs forward with two omni maps: worst %d/255", worst);
        if (worst > 2) rtSaveImage(def, "omni-deferred");
        UnloadImage(def);
    }
    for (int k = 0; k < 6; k++) UnloadImage(img[k]);
    RL_FREE(texels[0]); RL_FREE(texels[1]);
    shClearScene();
    RblUnloadShadowMap(&maps[0]); RblUnloadShadowMap(&maps[1]);
    omRigUnload(&rig);
}

// ---- cascades ------------------------------------------------------------------------------------
// A camera 1.6 above a floor looking ahead and down; 4 cascades of 256 texels over 0.3..60; a sun
// at elevation 60 from azimuth 20; a horizontal 1 x 1 card at height 0.6 three units ahead (cascade
// 0) and another at 4.6 whose shadow crosses the first blend band
#define CS_TILE 256
#define CS_VIEW 128
static Camera3D csCamera(double pan, double yawDeg)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    double a = yawDeg*PI/180.0, fx = 0.0, fz = -4.0;
    c.position = (Vector3){ (float)pan, 1.6f, 0.0f };
    c.target = (Vector3){ (float)(pan + fx*cos(a) - fz*sin(a)), 0.4f, (float)(fx*sin(a) + fz*cos(a)) };
    c.up = (Vector3){ 0.0f, 1.0f, 0.0f }; c.fovy = 45.0f; c.projection = CAMERA_PERSPECTIVE;
    return c;
}

static RblBillboard csCard(float x, float z)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.0f, 1.0f }; b.origin = (Vector2){ 0.5f, 0.5f };
    b.position = (Vector3){ x, 0.6f, z };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; b.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    return b;
}

static RblBillboard csFloor(void)
{
    RblBillboard b = ssFloor();
    b.size = (Vector2){ 200.0f, 200.0f }; b.origin = (Vector2){ 100.0f, 100.0f };
    return b;
}

typedef struct CsRig { Shader lit; Material m; Texture2D white; RblShadowMap map; RenderTexture2D view; RblLight sun; } CsRig;

static bool csLoad(CsRig *r, int cascades, int tile, float blend)
{
    memset(r, 0, sizeof(*r));
    r->sun = litDirectional((Vector3){ (float)(-cos(PI/3)*sin(PI/9)), (float)-sin(PI/3), (float)(-cos(PI/3)*cos(PI/9)) }, 1.0f);
    r->sun.color = WHITE;
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RblGetLightFeatures(&r->sun, 1); desc.shading.shadowMaps = 1;
    r->lit = RblLoadLitShader(desc);
    r->white = solidTexture(WHITE);
    r->m = LoadMaterialDefault();
    r->m.shader = r->lit;
    r->m.maps[MATERIAL_MAP_ALBEDO].texture = r->white;
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = tile; sd.cascades = cascades; sd.cascadeBlend = blend;
    r->map = RblLoadShadowMap(sd);
    r->view = LoadRenderTexture(CS_VIEW, CS_VIEW);
    return RblIsLitShaderValid(r->lit) && RblIsShadowMapValid(r->map);
}

static void csUnload(CsRig *r)
{
    shClearScene();
    UnloadRenderTexture(r->view);
    RblUnloadShadowMap(&r->map);
    MemFree(r->m.maps);
    UnloadTexture(r->white);
    RblUnloadLitShader(&r->lit);
}

// Fit to the camera, run every cascade's pass (floor and both cards), set the scene
static void csShadows(CsRig *r, Camera3D camera)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &r->sun; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    RT_CHECK(RblFitShadowCascades(&r->map, camera, 1.0f, 0.3f, 60.0f), "fit refused");
    for (int c = 0; c < RblShadowMapPasses(r->map); c++)
    {
        RT_CHECK(RblBeginShadowMapPass(&r->map, &scene, 0, c, (Vector3){ 0 }, 0.0f), "cascade %d refused", c);
        RblDrawBillboard(camera, r->m, csFloor());
        RblDrawBillboard(camera, r->m, csCard(0.0f, -3.0f));
        RblDrawBillboard(camera, r->m, csCard(1.5f, -3.8f));
        RblEndShadowMap(&r->map);
    }
    scene.shadowMaps = &r->map; scene.shadowMapCount = 1;
    RT_CHECK(RblSetScene(&scene), "scene rejected");
}

// The floor window [cx - w/2, cx + w/2] x [cz - w/2, cz + w/2] from straight above (row 0 at -z)
static Camera3D csTop(double cx, double cz, double w)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ (float)cx, 20.0f, (float)cz }; c.target = (Vector3){ (float)cx, 0.0f, (float)cz }; c.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    c.fovy = (float)w; c.projection = CAMERA_ORTHOGRAPHIC;
    return c;
}

static Image csRenderTop(CsRig *r, double cx, double cz, double w)
{
    Camera3D top = csTop(cx, cz, w);
    BeginTextureMode(r->view);
    ClearBackground(BLACK);
    BeginMode3D(top);
    RblDrawBillboard(top, r->m, csFloor());
    EndMode3D();
    EndTextureMode();
    return rtReadTarget(r->view);
}

static void test_shadows_cascade_splits_and_spheres_match_the_double_reference(void)
{
    CsRig r;
    RT_CHECK(csLoad(&r, 4, CS_TILE, 0.0f), "rig failed to load");
    RT_CHECK(RblShadowMapPasses(r.map) == 4 && r.map.casters.width == 4*CS_TILE && r.map.casters.height == CS_TILE, "4 cascades: %d passes, target %dx%d",
             RblShadowMapPasses(r.map), r.map.casters.width, r.map.casters.height);
    Camera3D cam = csCamera(0.37, 23.0);
    csShadows(&r, cam);
    const rbl__ShadowMapState *st = r.map.state;
    double n = (double)0.3f, f = 60.0, lambda = 0.75, blend = 0.1, worstSplit = 0.0, worstFit = 0.0, worstSnap = 0.0, worstGuard = 1e9;
    // Camera frame in double (raylib: forward to the target, right = forward x up)
    double e[3] = { cam.position.x, cam.position.y, cam.position.z }, fw[3] = { cam.target.x - e[0], cam.target.y - e[1], cam.target.z - e[2] };
    double fl = sqrt(fw[0]*fw[0] + fw[1]*fw[1] + fw[2]*fw[2]);
    for (int k = 0; k < 3; k++) fw[k] /= fl;
    double rt[3] = { -fw[2], 0.0, fw[0] }, rl = sqrt(rt[0]*rt[0] + rt[2]*rt[2]);
    rt[0] /= rl; rt[2] /= rl;
    double up[3] = { rt[1]*fw[2] - rt[2]*fw[1], rt[2]*fw[0] - rt[0]*fw[2], rt[0]*fw[1] - rt[1]*fw[0] }, h = tan(22.5*PI/180.0);
    double split[5];
    for (int i = 0; i <= 4; i++) split[i] = lambda*n*pow(f/n, i/4.0) + (1.0 - lambda)*(n + (f - n)*i/4.0);
    for (int i = 0; i <= 4; i++) worstSplit = fmax(worstSplit, fabs(st->split[i] - split[i])/split[i]);
    for (int c = 0; c < 4; c++)
    {
        // Every corner of the slice (widened by the previous cascade's band) lies in the sphere; the
        // farthest on it (the smallest sphere through both caps' rims)
        double lo = split[c] - ((c > 0)? blend*(split[c] - split[c - 1]) : 0.0), hi = split[c + 1], far = 0.0;
        for (int k = 0; k < 8; k++)
        {
            double d = (k & 4)? hi : lo, sx = (k & 1)? 1.0 : -1.0, sy = (k & 2)? 1.0 : -1.0, q[3], dd = 0.0;
            for (int a = 0; a < 3; a++) { q[a] = e[a] + fw[a]*d + rt[a]*sx*d*h + up[a]*sy*d*h; dd += pow(q[a] - st->fitCenter[c][a], 2.0); }
            far = fmax(far, sqrt(dd));
        }
        worstFit = fmax(worstFit, fabs(far - st->fitRadius[c])/st->fitRadius[c]);
        RT_CHECK(far <= st->fitRadius[c]*(1.0 + 1e-6), "cascade %d: a slice corner lies %.6g outside its sphere", c, far - st->fitRadius[c]);
        // The window: whole texels of a world-fixed grid, the sphere inside with the guard texels around
        double inv = st->tiles[c][0], texel = 1.0/(inv*CS_TILE), left = -st->tiles[c][1]/inv, bottom = -st->tiles[c][2]/inv;
        double cx = 0.0, cy = 0.0;
        for (int a = 0; a < 3; a++) { cx += (&st->lightView.right.x)[a]*st->fitCenter[c][a]; cy += (&st->lightView.up.x)[a]*st->fitCenter[c][a]; }
        worstSnap = fmax(worstSnap, fmax(fabs(left/texel - floor(left/texel + 0.5)), fabs(bottom/texel - floor(bottom/texel + 0.5))));
        double g[4] = { (cx - st->fitRadius[c] - left)/texel, (left + texel*CS_TILE - cx - st->fitRadius[c])/texel,
                        (cy - st->fitRadius[c] - bottom)/texel, (bottom + texel*CS_TILE - cy - st->fitRadius[c])/texel };
        for (int k = 0; k < 4; k++) worstGuard = fmin(worstGuard, g[k]);
        RT_CHECK(fabs(st->tiles[c][3] - split[c + 1]) <= 1e-5*split[c + 1], "cascade %d: far split %g (expected %g)", c, st->tiles[c][3], split[c + 1]);
        printf("    cascade %d: view depth %.3f..%.3f, sphere radius %.4f, texel %.5f\n", c, split[c], split[c + 1], st->fitRadius[c], texel);
    }
    printf("    splits within %.2g (relative) of lambda-0.75 practical split; spheres within %.2g of the slice's farthest corner; windows on whole texels within %.2g; guard >= %.2f texels\n",
           worstSplit, worstFit, worstSnap, worstGuard);
    RT_CHECK(worstSplit < 1e-12, "splits off the practical split by %g", worstSplit);
    // (the camera's float position and target feed both: agreement to float precision)
    RT_CHECK(worstFit < 1e-6, "a sphere is %g larger than its slice needs", worstFit);
    RT_CHECK(worstSnap < 1e-3, "a window is off the texel grid by %g texels", worstSnap);
    RT_CHECK(worstGuard >= RBL_SHADOW_MAX_FILTER/2 + 1, "a sphere comes within %.2f texels of its tile's edge", worstGuard);
    // The debug view from above and behind: each cascade's lines in its colour
    Camera3D overview = litCamera((Vector3){ 30.0f, 60.0f, 50.0f }, (Vector3){ 0.0f, 0.0f, -25.0f });
    BeginTextureMode(r.view);
    ClearBackground(BLACK);
    BeginMode3D(overview);
    RblDrawShadowCascades(r.map);
    EndMode3D();
    EndTextureMode();
    Image dbg = rtReadTarget(r.view);
    int seen[4] = { 0 };
    for (int y = 0; y < CS_VIEW; y++)
        for (int x = 0; x < CS_VIEW; x++)
        {
            Color p = rtPixel(dbg, x, y);
            for (int c = 0; c < 4; c++) { Color k = RblShadowCascadeColor(c); seen[c] += (abs(p.r - k.r) < 8) && (abs(p.g - k.g) < 8) && (abs(p.b - k.b) < 8); }
        }
    printf("    debug view: pixels in each cascade's colour %d %d %d %d\n", seen[0], seen[1], seen[2], seen[3]);
    for (int c = 0; c < 4; c++) RT_CHECK(seen[c] > 10, "debug view: cascade %d's colour on %d pixels only", c, seen[c]);
    if (rtFailuresInCurrentTest() > 0) rtSaveImage(dbg, "debug");
    UnloadImage(dbg);
    csUnload(&r);
}

// Sub-pixel position of a shadow's left edge on each row of a top view (the midpoint crossing
// between the lit column 0 and the shadowed last column), in world units (1e30: none on that row)
static void csEdge(Image img, double x0, double w, double *rows)
{
    for (int y = 0; y < CS_VIEW; y++)
    {
        double lit = rtPixel(img, 0, y).r, dark = rtPixel(img, CS_VIEW - 1, y).r, mid = 0.5*(lit + dark);
        rows[y] = 1e30;
        for (int x = 1; x < CS_VIEW; x++)
        {
            double a = rtPixel(img, x - 1, y).r, b = rtPixel(img, x, y).r;
            if ((a >= mid) && (b < mid)) { rows[y] = x0 + ((x - 0.5) + (a - mid)/(a - b))*w/CS_VIEW; break; }
        }
    }
}

// The card three units ahead casts an edge inside cascade 0; the camera pans sideways by 1/76 of a
// unit per frame and turns by 0.6 degrees per frame (16 frames each). Measured on the fixed floor
// against the first frame: the edge's sub-pixel position on each of the 128 rows (the worst row)
// and every pixel's value. Goal (the issue): no row's edge moves by more than a texel of the
// finest cascade. Snapped windows of spheres whose radius a pan or turn never changes hold every
// texel where it was, so the floor renders the same: no pixel changes by more than 1/255 (an
// unsnapped window moves the PCF weights: edge pixels flicker)
static void test_shadows_cascade_edges_hold_still_while_the_camera_pans_and_turns(void)
{
    CsRig r;
    RT_CHECK(csLoad(&r, 4, CS_TILE, 0.0f), "rig failed to load");
    const double cx = -0.6, cz = -3.3, w = 0.8;
    double worst[2] = { 0.0, 0.0 }, texel = 0.0, first[CS_VIEW], rows[CS_VIEW];
    int pixel[2] = { 0, 0 }, edgeRows = 0;
    for (int motion = 0; motion < 2; motion++)
    {
        Image base = { 0 };
        for (int i = 0; i < 16; i++)
        {
            Camera3D cam = motion? csCamera(0.0, 0.6*i) : csCamera(i/76.0, 0.0);
            csShadows(&r, cam);
            texel = 1.0/(r.map.state->tiles[0][0]*CS_TILE);
            Image img = csRenderTop(&r, cx, cz, w);
            csEdge(img, cx - 0.5*w, w, rows);
            if (i == 0) { memcpy(first, rows, sizeof(rows)); base = img; edgeRows = 0; for (int y = 0; y < CS_VIEW; y++) edgeRows += (rows[y] < 1e29); continue; }
            for (int y = 0; y < CS_VIEW; y++)
                if ((rows[y] < 1e29) && (first[y] < 1e29)) worst[motion] = fmax(worst[motion], fabs(rows[y] - first[y]));
                else if ((rows[y] < 1e29) != (first[y] < 1e29)) worst[motion] = 1e30;
            for (int y = 0; y < CS_VIEW; y++)
                for (int x = 0; x < CS_VIEW; x++) { int d = abs((int)rtPixel(img, x, y).r - rtPixel(base, x, y).r); if (d > pixel[motion]) pixel[motion] = d; }
            if ((i == 15) && (rtFailuresInCurrentTest() > 0)) rtSaveImage(img, motion? "turn" : "pan");
            UnloadImage(img);
        }
        UnloadImage(base);
    }
    printf("    shadow edge over 16 frames, %d rows (finest cascade texel %.4f): worst row moves %.3f texels (pan), %.3f (turn); worst pixel change %d/255 (pan), %d/255 (turn)\n",
           edgeRows, texel, worst[0]/texel, worst[1]/texel, pixel[0], pixel[1]);
    RT_CHECK(edgeRows > 100, "the edge crosses only %d rows of the window (test setup)", edgeRows);
    RT_CHECK(worst[0] <= texel && worst[1] <= texel, "edges move by %.3f (pan) and %.3f (turn) texels of the finest cascade", worst[0]/texel, worst[1]/texel);
    RT_CHECK(pixel[0] <= 1 && pixel[1] <= 1, "floor pixels change by %d/255 (pan) and %d/255 (turn) while the camera moves", pixel[0], pixel[1]);
    csUnload(&r);
}

// Inside the last tenth of cascade 0's depth range the lookup mixes cascade 1's in linearly: the
// rendered value there is the linear-light mix of cascade 0 alone (blend off) and cascade 1 alone
// (blend off, cascade 0's far split moved to the band's start), by the band weight the CPU computes
// from the camera in double, within 2/255
static void test_shadows_cascade_blend_band_mixes_the_two_cascades_linearly(void)
{
    CsRig r;
    RT_CHECK(csLoad(&r, 4, 64, 0.0f), "rig failed to load");
    Camera3D cam = csCamera(0.0, 0.0);
    const double cx = 0.9, cz = -4.2, w = 0.8;
    Image img[3];
    double start = 0.0, end = 0.0;
    for (int k = 0; k < 3; k++)
    {
        csShadows(&r, cam);
        rbl__ShadowMapState *st = r.map.state;
        end = st->split[1]; start = end - 0.1*(st->split[1] - st->split[0]);
        if (k > 0) st->blend = 0.0;                              // one cascade per point
        if (k == 2) st->tiles[0][3] = (float)start;              // the band's points in cascade 1
        if (k > 0) { RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &r.sun; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
                     scene.shadowMaps = &r.map; scene.shadowMapCount = 1; RT_CHECK(RblSetScene(&scene), "scene rejected"); }
        img[k] = csRenderTop(&r, cx, cz, w);
    }
    double e[3] = { cam.position.x, cam.position.y, cam.position.z }, fw[3] = { cam.target.x - e[0], cam.target.y - e[1], cam.target.z - e[2] };
    double fl = sqrt(fw[0]*fw[0] + fw[1]*fw[1] + fw[2]*fw[2]);
    int band = 0, differing = 0, wrong = 0, worst = 0;
    for (int y = 0; y < CS_VIEW; y++)
        for (int x = 0; x < CS_VIEW; x++)
        {
            double px = cx - 0.5*w + (x + 0.5)*w/CS_VIEW, pz = cz - 0.5*w + (y + 0.5)*w/CS_VIEW;
            double depth = ((px - e[0])*fw[0] + (0.0 - e[1])*fw[1] + (pz - e[2])*fw[2])/fl;
            double t = (depth - start)/(end - start);
            if ((t < 0.02) || (t > 0.98)) continue;                 // a hair from the band's ends: either side may round
            int a = rtPixel(img[0], x, y).r, b = rtPixel(img[1], x, y).r, c = rtPixel(img[2], x, y).r;
            double mixed = (1.0 - t)*omLinear(b) + t*omLinear(c);
            double s = (mixed <= 0.0031308)? mixed*12.92 : 1.055*pow(mixed, 1.0/2.4) - 0.055;
            int d = (int)fabs(a - s*255.0 + 0.0) ;
            band++;
            differing += (abs(b - c) >= 8);
            if (d > worst) worst = d;
            if (d > 2) wrong++;
        }
    printf("    blend band (view depth %.3f..%.3f): %d pixels, %d where the two cascades differ by >= 8/255; worst %d/255 from the linear mix\n", start, end, band, differing, worst);
    RT_CHECK(band > 500 && differing > 20, "test setup: %d band pixels, %d where the cascades differ", band, differing);
    RT_CHECK(wrong == 0, "%d band pixels off the linear mix of the two cascades (worst %d/255)", wrong, worst);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(img[0], "blend"); rtSaveImage(img[1], "c0"); rtSaveImage(img[2], "c1"); }
    for (int k = 0; k < 3; k++) UnloadImage(img[k]);
    csUnload(&r);
}

// Receivers compile the kinds of map they sample (issue 26: a feature the user does not use costs
// nothing). One lit program receiving 2 maps is drawn with a sun's single map, then with the sun's
// map and a point light's omni map, then with the omni map alone, then with none. The single-map
// draw uses the program as loaded, whose linked code reads no tile uniform (rblShadowTiles: only omni
// faces and cascades read it, so code for either, even behind a run-time branch, keeps it active);
// the mixed scene draws through a variant that compiled map 1 as omni. The lights add up: in linear
// light, both maps + no maps = sun map alone + omni map alone at every pixel (within 0.02: four
// 8-bit sRGB roundings), which fails if the mixed scene drops or misreads either map. The G-buffer
// receiving the same mixed scene agrees with forward within 2/255.
static double omLinearOf(Image img, int x, int y)
{
    Color c = rtPixel(img, x, y);
    return (omLinear(c.r) + omLinear(c.g) + omLinear(c.b))/3.0;
}

static void test_shadows_single_map_receivers_hold_no_omni_or_cascade_code_and_mixed_scenes_add_up(void)
{
    const Vector3 lpos = { 1.4f, 1.3f, 0.6f };
    RblLight lights[2] = { litDirectional((Vector3){ 0.35f, -1.0f, 0.25f }, 0.45f), litPoint(lpos, 0.7f, 12.0f) };
    lights[1].color = WHITE;
    OmRig rig = omRigLoad(lights, 2, 2);
    Material m = rig.m;
    Camera3D top = rig.top;
    RblScene *scene = &rig.scene;
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 256;
    RblShadowMap sun = RblLoadShadowMap(sd);
    sd.omni = true;
    RblShadowMap omni = RblLoadShadowMap(sd);
    RT_CHECK(RblIsShadowMapValid(sun) && RblIsShadowMapValid(omni), "maps failed to load");
    // Casters: a card high up for the sun (its shadow lands left of the light), one under the point light
    RblBillboard cards[2];
    memset(cards, 0, sizeof(cards));
    for (int c = 0; c < 2; c++)
    {
        cards[c].facing = RBL_FACING_FIXED; cards[c].axis = (Vector3){ 0.0f, 1.0f, 0.0f }; cards[c].up = (Vector3){ 0.0f, 0.0f, -1.0f };
        cards[c].size = (c == 0)? (Vector2){ 1.2f, 1.2f } : (Vector2){ 0.5f, 0.5f };
        cards[c].origin = (Vector2){ cards[c].size.x*0.5f, cards[c].size.y*0.5f };
    }
    cards[0].position = (Vector3){ -2.0f, 1.5f, -1.0f };
    cards[1].position = (Vector3){ lpos.x + 0.3f, 0.7f, lpos.z - 0.2f };
    if (RblBeginShadowMap(&sun, scene, 0, (Vector3){ 0.0f, 0.5f, 0.0f }, 6.0f))
    {
        for (int c = 0; c < 2; c++) RblDrawBillboard(top, m, cards[c]);
        RblEndShadowMap(&sun);
    }
    else RT_CHECK(false, "sun pass refused");
    for (int pass = 0; pass < RblShadowMapPasses(omni); pass++)
    {
        RT_CHECK(RblBeginShadowMapPass(&omni, scene, 1, pass, (Vector3){ 0 }, 0.0f), "omni face %d refused", pass);
        for (int c = 0; c < 2; c++) RblDrawBillboard(top, m, cards[c]);
        RblEndShadowMap(&omni);
    }
    // Renders: sun map alone (the program as loaded), both maps, omni map alone, none
    RblShadowMap lists[4][2] = { { sun }, { sun, omni }, { omni }, { sun } };
    const int counts[4] = { 1, 2, 1, 0 };
    Image img[4];
    rbl__Program *base = rbl__findLit(rig.lit.id), *drawn[4] = { NULL };
    for (int k = 0; k < 4; k++)
    {
        scene->shadowMaps = lists[k]; scene->shadowMapCount = counts[k];
        img[k] = omForwardFloor(&rig);
        drawn[k] = (base != NULL)? rbl__shadowVariant(base) : NULL;     // what that draw used
    }
    RT_CHECK(base != NULL, "the lit program is not in the registry");
    if (base != NULL)
    {
        RT_CHECK(drawn[0] == base, "the single-map scene drew through a variant, not the program as loaded");
        RT_CHECK(base->key.shadowKinds == (RBL__SHADOW_CODE_DEFAULT | (RBL__SHADOW_CODE_DEFAULT << 4)), "the program as loaded compiled map kinds %#x", base->key.shadowKinds);
        RT_CHECK(!litHasUniform(base->shader, "rblShadowTiles"), "a program receiving single maps keeps rblShadowTiles: omni or cascade code compiled in");
        RT_CHECK(litHasUniform(base->shader, "rblShadowParams"), "test setup: the single-map program samples no shadow map");
        RT_CHECK((drawn[1] != NULL) && (drawn[1] != base) && (((drawn[1]->key.shadowKinds >> 4) & 15)/4 == 1) && ((drawn[1]->key.shadowKinds & 15)/4 == 0),
                 "the mixed scene did not draw through a variant with map 0 single and map 1 omni");
        RT_CHECK((drawn[1] != NULL) && litHasUniform(drawn[1]->shader, "rblShadowTiles"), "the omni variant reads no tile uniform");
        RT_CHECK((drawn[2] != NULL) && (drawn[2] != drawn[1]) && ((drawn[2]->key.shadowKinds & 15)/4 == 1), "the omni-only scene did not draw through an omni variant");
        RT_CHECK(drawn[3] == base, "the scene without maps did not draw through the program as loaded");
    }
    int sunDark = 0, omniDark = 0, bad = 0, bx = -1, by = -1;
    double worst = 0.0;
    for (int y = 0; y < OM_VIEW; y++)
        for (int x = 0; x < OM_VIEW; x++)
        {
            double s = omLinearOf(img[0], x, y), both = omLinearOf(img[1], x, y), o = omLinearOf(img[2], x, y), none = omLinearOf(img[3], x, y);
            sunDark += (none - s > 0.05);
            omniDark += (none - o > 0.05);
            double e = fabs(both + none - s - o);
            if (e > worst) { worst = e; bx = x; by = y; }
            bad += (e > 0.02);
        }
    printf("    mixed scene: %d pixels in the sun map's shadow, %d in the omni map's; both + none - sun - omni worst %.4f linear at (%d, %d), %d beyond 0.02\n",
           sunDark, omniDark, worst, bx, by, bad);
    RT_CHECK(sunDark > 100, "the sun's map alone darkens %d pixels (its card's shadow: over 100)", sunDark);
    RT_CHECK(omniDark > 40, "the omni map alone darkens %d pixels (its card's shadow: over 40)", omniDark);
    RT_CHECK(bad == 0, "%d pixels where the mixed scene is not the sum of each map alone (worst %.4f linear)", bad, worst);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(img[0], "sun"); rtSaveImage(img[1], "both"); rtSaveImage(img[2], "omni"); rtSaveImage(img[3], "none"); }

    // Deferred: the G-buffer's passes receiving the mixed scene pick their variant too
    if (rbl__glsl() >= 300)
    {
        scene->shadowMaps = lists[1]; scene->shadowMapCount = 2;
        Image def = omDeferredFloor(RblGetLightFeatures(lights, 2), scene, m, top, rig.target);
        int wx = 0, wy = 0, dworst = omWorstChannel(def, img[1], &wx, &wy);
        printf("    deferred vs forward, sun map + omni map: worst %d/255\n", dworst);
        RT_CHECK(dworst <= 2, "deferred vs forward with a single and an omni map: worst %d/255", dworst);
        if (dworst > 2) rtSaveImage(def, "mixed-deferred");
        UnloadImage(def);
    }
    for (int k = 0; k < 4; k++) UnloadImage(img[k]);
    RblUnloadShadowMap(&sun);
    RblUnloadShadowMap(&omni);
    omRigUnload(&rig);
}

// An omni map without caster identities (RblShadowDesc.selfShadow: receivers read its depth texture,
// the perspective depth format compiled in) shadows a floor as the casters target's omni map does:
// the same pixels darken (a card under a point light, seen from above), on every context (ES 2 and
// GL 2.1 sample the depth texture through texture2D).
static void test_shadows_omni_depth_texture_maps_shadow_as_the_casters_target_does(void)
{
    const Vector3 lpos = { 0.3f, 1.4f, -0.2f };
    RblLight light = litPoint(lpos, 0.9f, 12.0f);
    light.color = WHITE;
    OmRig rig = omRigLoad(&light, 1, 1);
    Material m = rig.m;
    Camera3D top = rig.top;
    RblScene *scene = &rig.scene;
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 256; sd.omni = true;
    RblShadowMap maps[2];
    maps[0] = RblLoadShadowMap(sd);
    sd.selfShadow = true;
    maps[1] = RblLoadShadowMap(sd);
    RT_CHECK(RblIsShadowMapValid(maps[0]) && RblIsShadowMapValid(maps[1]), "maps failed to load");
    RblBillboard card;
    memset(&card, 0, sizeof(card));
    card.facing = RBL_FACING_FIXED; card.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; card.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    card.size = (Vector2){ 0.6f, 0.6f }; card.origin = (Vector2){ 0.3f, 0.3f };
    card.position = (Vector3){ lpos.x + 0.4f, 0.7f, lpos.z + 0.1f };
    for (int k = 0; k < 2; k++)
        for (int pass = 0; pass < RblShadowMapPasses(maps[k]); pass++)
        {
            RT_CHECK(RblBeginShadowMapPass(&maps[k], scene, 0, pass, (Vector3){ 0 }, 0.0f), "map %d face %d refused", k, pass);
            RblDrawBillboard(top, m, card);
            RblEndShadowMap(&maps[k]);
        }
    Image img[3];
    int code[3] = { -1, -1, -1 };
    rbl__Program *base = rbl__findLit(rig.lit.id);
    for (int k = 0; k < 3; k++)
    {
        scene->shadowMaps = (k < 2)? &maps[k] : NULL; scene->shadowMapCount = (k < 2)? 1 : 0;
        img[k] = omForwardFloor(&rig);
        rbl__Program *drawn = (base != NULL)? rbl__shadowVariant(base) : NULL;
        code[k] = (drawn != NULL)? (drawn->key.shadowKinds & 15) : -1;
    }
    RT_CHECK((code[0] == 7) && (code[1] == 5), "drawn with map codes %d and %d (omni casters target 7, omni depth texture 5)", code[0], code[1]);
    int dark[2] = { 0, 0 }, differ = 0;
    for (int y = 0; y < OM_VIEW; y++)
        for (int x = 0; x < OM_VIEW; x++)
        {
            int none = rtPixel(img[2], x, y).g, a = rtPixel(img[0], x, y).g, b = rtPixel(img[1], x, y).g;
            dark[0] += (none - a > 10); dark[1] += (none - b > 10);
            differ += (abs(a - b) > 3);
        }
    printf("    omni floor shadow: casters target %d dark pixels, depth texture %d; %d pixels differ by more than 3/255\n", dark[0], dark[1], differ);
    RT_CHECK(dark[0] > 60, "the casters target's omni map darkens %d pixels (its card's shadow: over 60)", dark[0]);
    RT_CHECK(dark[1] > 60, "the depth texture's omni map darkens %d pixels (its card's shadow: over 60)", dark[1]);
    RT_CHECK(differ*20 <= dark[0], "%d pixels differ by more than 3/255 between the two formats (over 5%% of %d shadowed)", differ, dark[0]);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(img[0], "casters"); rtSaveImage(img[1], "depth"); rtSaveImage(img[2], "none"); }
    for (int k = 0; k < 3; k++) UnloadImage(img[k]);
    RblUnloadShadowMap(&maps[0]);
    RblUnloadShadowMap(&maps[1]);
    omRigUnload(&rig);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_OMNI_CASCADES_TESTS \
    RT_TEST(test_shadows_omni_cube_faces_hold_the_double_precision_distances), \
    RT_TEST(test_shadows_two_omni_lights_match_a_double_precision_lookup_forward_and_deferred), \
    RT_TEST(test_shadows_cascade_splits_and_spheres_match_the_double_reference), \
    RT_TEST(test_shadows_cascade_edges_hold_still_while_the_camera_pans_and_turns), \
    RT_TEST(test_shadows_cascade_blend_band_mixes_the_two_cascades_linearly), \
    RT_TEST(test_shadows_single_map_receivers_hold_no_omni_or_cascade_code_and_mixed_scenes_add_up), \
    RT_TEST(test_shadows_omni_depth_texture_maps_shadow_as_the_casters_target_does)
