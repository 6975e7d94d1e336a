// The viewer (GPU, headless): orthographic cameras and two-sided cards, against the double reference.
// Orthographic: every ray is parallel, so the view vector is the camera's back direction everywhere
// (not eye - position) and fog runs along the view axis; a plane on every billboard path, a sphere
// Model (RblDrawModel and raylib's own DrawModel) and the G-buffer, each with a perspective control.
// Two-sided: a card seen from behind is shaded on the side the viewer sees (its mirror image through
// its plane) and is not culled, forward and deferred; the caller's culling state survives front-only
// draws; the back side receives shadows; an open Model drawn without culling is two-sided too.
// Included by test_gpu_main.c after test_deferred.c.

// Orthographic camera showing `height` world units vertically (raylib's fovy under CAMERA_ORTHOGRAPHIC)
static Camera3D viewOrtho(Vector3 position, Vector3 target, float height)
{
    Camera3D c = litCamera(position, target);
    c.projection = CAMERA_ORTHOGRAPHIC;
    c.fovy = height;
    return c;
}

// The same view as a perspective camera (the control): the eye where the orthographic one stands
static Camera3D viewPerspective(Camera3D ortho)
{
    Camera3D c = ortho;
    c.projection = CAMERA_PERSPECTIVE;
    c.fovy = 45.0f;
    return c;
}

static const char *viewProjectionName(Camera3D c) { return (c.projection == CAMERA_ORTHOGRAPHIC)? "ortho" : "persp"; }

// ---- deferred render of a LitScene's plane (display output), for litCompare -------------------
static Image viewRenderDeferredPlane(const LitScene *sc, bool *ok)
{
    RblLitShaderDesc desc = litProgramDesc(sc, 0);
    RblGBuffer g = RblLoadGBuffer(defGBufferDesc(&desc, LIT_TARGET, LIT_TARGET));
    desc.deferred = true;
    Shader geo = RblLoadLitShader(desc);
    RblScene scene = litSceneOf(sc);
    *ok = RblIsGBufferValid(g) && RblIsLitShaderValid(geo) && RblSetScene(&scene);
    Texture2D albedo = solidTexture(sc->albedo), normal = solidTexture(sc->normal);
    Material m = LoadMaterialDefault();
    m.shader = geo;
    rtSetMaterialValues(&m, sc->values);
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    if (sc->normalMap) m.maps[MATERIAL_MAP_NORMAL].texture = normal;
    if (*ok && RblBeginGBuffer(&g, sc->camera))
    {
        litDrawPlane(sc, m);
        RblEndGBuffer(&g);
        *ok = RblDrawDeferredLights(&g);
    }
    else *ok = false;
    RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    if (*ok) RblResolveGBuffer(&g);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    UnloadTexture(albedo); UnloadTexture(normal);
    MemFree(m.maps);
    RblUnloadLitShader(&geo);
    RblUnloadGBuffer(&g);
    return img;
}

// Forward (display + float, finite) or deferred render of the scene's plane against the reference
static LitError viewCheckPlane(const LitScene *sc, bool deferred, const char *name, double maxTol, double meanTol)
{
    if (!deferred) return litCheckAgainstReference(sc, name, maxTol, meanTol);
    bool ok = false;
    Image img = viewRenderDeferredPlane(sc, &ok);
    LitError e = litCompare(sc, img);
    RT_CHECK(ok, "%s: deferred frame refused", name);
    RT_CHECK(e.pixels > LIT_TARGET*LIT_TARGET/8, "%s: only %d interior pixels compared", name, e.pixels);
    RT_CHECK(e.max <= maxTol && e.mean <= meanTol, "%s: error max %.0f mean %.3f /255 (allowed %.0f, %.2f)", name, e.max, e.mean, maxTol, meanTol);
    if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, name);
    UnloadImage(img);
    return e;
}

// ---- a triangle mesh seen through each pixel (double precision) -------------------------------
// The GPU interpolates vertex attributes with the world-space barycentrics of the point a pixel's
// centre sees (perspective-correct; under a parallel projection they are the screen's), so the
// reference casts that pixel's ray, finds the nearest triangle and interpolates the vertex normals there.
typedef struct ViewMesh { int triangles; D3 *p, *n; } ViewMesh;     // 3 per triangle

static ViewMesh viewMeshOf(Mesh mesh, D3 offset)
{
    ViewMesh v;
    v.triangles = mesh.triangleCount;
    v.p = (D3 *)malloc(sizeof(D3)*3*(size_t)v.triangles);
    v.n = (D3 *)malloc(sizeof(D3)*3*(size_t)v.triangles);
    for (int t = 0; t < v.triangles; t++)
        for (int k = 0; k < 3; k++)
        {
            int i = (mesh.indices != NULL)? mesh.indices[t*3 + k] : t*3 + k;
            v.p[t*3 + k] = dAdd(d3(mesh.vertices[i*3], mesh.vertices[i*3 + 1], mesh.vertices[i*3 + 2]), offset);
            v.n[t*3 + k] = d3(mesh.normals[i*3], mesh.normals[i*3 + 1], mesh.normals[i*3 + 2]);
        }
    return v;
}

static void viewMeshFree(ViewMesh *v) { free(v->p); free(v->n); memset(v, 0, sizeof(*v)); }

// Nearest hit of the pixel's ray (Moller-Trumbore): position and interpolated unit normal; false = miss
static bool viewMeshPixel(const ViewMesh *m, Camera3D cam, int w, int h, int px, int py, D3 *hit, D3 *normal)
{
    D3 o, d;
    refPixelRay(cam, w, h, px, py, &o, &d);
    double best = INFINITY;
    for (int t = 0; t < m->triangles; t++)
    {
        D3 a = m->p[t*3], e1 = dSub(m->p[t*3 + 1], a), e2 = dSub(m->p[t*3 + 2], a);
        D3 q = dCross(d, e2);
        double det = dDot(e1, q);
        if (fabs(det) < 1e-300) continue;
        D3 s = dSub(o, a);
        double u = dDot(s, q)/det;
        if ((u < 0.0) || (u > 1.0)) continue;
        D3 r = dCross(s, e1);
        double v = dDot(d, r)/det;
        if ((v < 0.0) || (u + v > 1.0)) continue;
        double dist = dDot(e2, r)/det;
        if ((dist <= 0.0) || (dist >= best)) continue;
        best = dist;
        *hit = dAdd(o, dScale(d, dist));
        *normal = dNorm(dAdd(dAdd(dScale(m->n[t*3], 1.0 - u - v), dScale(m->n[t*3 + 1], u)), dScale(m->n[t*3 + 2], v)));
    }
    return best < INFINITY;
}

// A lit sphere Model: scene, material and the reference of every pixel it covers
typedef struct ViewSphere {
    Camera3D camera;
    RblLitShaderDesc desc;          // compiled features
    RtMaterialValues values;
    RblLight lights[3];
    int count;
    RblFog fog;
    Color albedo, ambient;
} ViewSphere;

#define VIEW_SPHERE_RADIUS 1.0f
static const Vector3 viewSpherePosition = { 0.2f, -0.1f, 0.0f };

typedef struct ViewError { double max, mean; int pixels; } ViewError;

// Covered pixels whose 4 neighbours see the mesh too (silhouette pixels are partly background)
// against round(reference*255)
static ViewError viewCompareSphere(const ViewSphere *vs, const ViewMesh *mesh, Image img)
{
    ViewError e;
    memset(&e, 0, sizeof(e));
    RefParams d;
    memset(&d, 0, sizeof(d));
    d.brdf = vs->desc.shading.brdf;
    d.specular = vs->values.specular; d.shininess = vs->values.shininess; d.specularColor = vs->values.specularColor;
    d.roughness = vs->values.roughness; d.metalness = vs->values.metalness;
    d.fog = vs->fog; d.tonemap = vs->desc.shading.tonemap;
    RefEnvironment env;
    memset(&env, 0, sizeof(env));
    env.ambient = vs->ambient;
    double sum = 0.0;
    for (int py = 1; py < LIT_TARGET - 1; py++)
        for (int px = 1; px < LIT_TARGET - 1; px++)
        {
            D3 p, n, q, qn;
            if (!viewMeshPixel(mesh, vs->camera, LIT_TARGET, LIT_TARGET, px, py, &p, &n)) continue;
            if (!viewMeshPixel(mesh, vs->camera, LIT_TARGET, LIT_TARGET, px - 1, py, &q, &qn) || !viewMeshPixel(mesh, vs->camera, LIT_TARGET, LIT_TARGET, px + 1, py, &q, &qn) ||
                !viewMeshPixel(mesh, vs->camera, LIT_TARGET, LIT_TARGET, px, py - 1, &q, &qn) || !viewMeshPixel(mesh, vs->camera, LIT_TARGET, LIT_TARGET, px, py + 1, &q, &qn)) continue;
            Color c = rtPixel(img, px, py);
            if (c.a == 0) continue;
            RefSurface s;
            memset(&s, 0, sizeof(s));
            s.position = p; s.normal = n; s.albedo = refLinear(vs->albedo); s.specularMap = -1.0; s.occlusion = 1.0;
            RefRgb ref = refFinishAt(&d, refShadeView(&d, vs->lights, vs->count, &env, &s, refViewVector(vs->camera, p)), refViewDistance(vs->camera, p));
            const double got[3] = { c.r, c.g, c.b }, want[3] = { ref.r*255.0, ref.g*255.0, ref.b*255.0 };
            for (int ch = 0; ch < 3; ch++)
            {
                double err = fabs(got[ch] - floor(want[ch] + 0.5));
                if (err > e.max) e.max = err;
                sum += err;
            }
            e.pixels++;
        }
    e.mean = (e.pixels > 0)? sum/(3.0*e.pixels) : 0.0;
    return e;
}

// Renders the sphere: path 0 RblDrawModel forward, 1 raylib's DrawModel forward (the values the
// program last received: RblDrawModel runs first), 2 RblDrawModel into the G-buffer
static Image viewRenderSphere(const ViewSphere *vs, Model *model, int path, bool *ok)
{
    RblLitShaderDesc desc = vs->desc;
    desc.maxLights = vs->count;
    desc.shading.lightFeatures = RblGetLightFeatures(vs->lights, vs->count);
    desc.shading.fog = vs->fog.mode;
    RblGBuffer g;
    memset(&g, 0, sizeof(g));
    if (path == 2) { g = RblLoadGBuffer(defGBufferDesc(&desc, LIT_TARGET, LIT_TARGET)); desc.deferred = true; }
    Shader lit = RblLoadLitShader(desc);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = vs->lights; scene.lightCount = vs->count; scene.ambient = vs->ambient; scene.fog = vs->fog;
    *ok = RblIsLitShaderValid(lit) && RblSetScene(&scene) && ((path != 2) || RblIsGBufferValid(g));
    Texture2D albedo = solidTexture(vs->albedo);
    Material keep = model->materials[0];
    Material m = LoadMaterialDefault();
    m.shader = lit;
    rtSetMaterialValues(&m, vs->values);
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    model->materials[0] = m;
    RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
    if (path == 2)
    {
        if (*ok && RblBeginGBuffer(&g, vs->camera))
        {
            RblDrawModel(*model, viewSpherePosition, 1.0f, WHITE);
            RblEndGBuffer(&g);
            *ok = RblDrawDeferredLights(&g);
        }
        else *ok = false;
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        if (*ok) RblResolveGBuffer(&g);
        EndTextureMode();
    }
    else
    {
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        BeginMode3D(vs->camera);
        RblDrawModel(*model, viewSpherePosition, 1.0f, WHITE);
        if (path == 1)
        {
            ClearBackground(BLANK);             // only raylib's own draw stays
            DrawModel(*model, viewSpherePosition, 1.0f, WHITE);
        }
        EndMode3D();
        EndTextureMode();
    }
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    model->materials[0] = keep;
    MemFree(m.maps);
    UnloadTexture(albedo);
    RblUnloadLitShader(&lit);
    if (path == 2) RblUnloadGBuffer(&g);
    return img;
}

// ---- orthographic cameras -------------------------------------------------------------------------
// Plane on every billboard path (immediate fixed plane, batched and instanced camera-plane
// billboards), forward and deferred, tight highlights: the view vector is the camera's back direction
static void test_view_orthographic_plane_on_every_path_matches_the_double_reference(void)
{
    struct { const char *name; int brdf; float shininess, roughness, metalness; } materials[5] = {
        { "blinn-phong n=64", RBL_BRDF_BLINN_PHONG, 64.0f, 0, 0 }, { "blinn-phong n=256", RBL_BRDF_BLINN_PHONG, 256.0f, 0, 0 },
        { "ggx r=0.1 m=0", RBL_BRDF_GGX, 0, 0.1f, 0 }, { "ggx r=0.25 m=1", RBL_BRDF_GGX, 0, 0.25f, 1 }, { "ggx r=0.5 m=0", RBL_BRDF_GGX, 0, 0.5f, 0 },
    };
    const char *lightNames[3] = { "point", "directional", "spot" };
    RblLight lights[3] = {
        litPoint((Vector3){ 0.6f, 0.4f, 1.2f }, 2.0f, 6.0f),
        litDirectional((Vector3){ -0.2f, -0.3f, -1.0f }, 1.0f),
        litSpot((Vector3){ 0.3f, -0.2f, 2.0f }, (Vector3){ -0.1f, 0.1f, -1.0f }, 15.0f, 35.0f, 6.0f),
    };
    const char *pathNames[4] = { "immediate fixed", "batched camera-plane", "instanced camera-plane", "deferred fixed" };
    const Camera3D orthos[2] = { viewOrtho((Vector3){ 0.5f, 0.3f, 3.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, 5.0f),
                                 viewOrtho((Vector3){ 0.0f, -5.0f, 3.0f }, (Vector3){ 0.0f, 0.5f, 0.0f }, 5.0f) };
    printf("    %-8s %-6s %-24s %-18s %-12s %6s %8s %7s\n", "view", "proj", "path", "material", "light", "max", "mean", "pixels");
    double worst[2] = { 0.0, 0.0 }, worstMean[2] = { 0.0, 0.0 };
    for (int proj = 0; proj < 2; proj++)
        for (int view = 0; view < 2; view++)
            for (int path = 0; path < 4; path++)
                for (int mi = 0; mi < 5; mi++)
                    for (int li = 0; li < 3; li++)
                    if ((path < 2) || rtGlsl3())        // instanced and deferred: GLSL 3 contexts
                    {
                        // Deferred rows: moderate highlights (12+12-bit normals, RGBA16F accumulation; the
                        // perspective control of a tight metal highlight is 3/255 off there too) and no
                        // directional light (a uniform image: the mean is one rounding of one colour)
                        if ((path == 3) && ((mi == 1) || (mi == 2) || (mi == 3) || (li == 1))) continue;
                        LitScene sc = litScene(materials[mi].brdf);
                        sc.values.shininess = materials[mi].shininess;
                        sc.values.roughness = materials[mi].roughness;
                        sc.values.metalness = materials[mi].metalness;
                        sc.lights[0] = lights[li];
                        sc.count = 1;
                        sc.camera = (proj == 1)? orthos[view] : viewPerspective(orthos[view]);
                        sc.path = (path == 3)? LIT_PATH_IMMEDIATE : path;
                        sc.facing = ((path == 1) || (path == 2))? RBL_FACING_CAMERA_PLANE : RBL_FACING_FIXED;
                        char name[128];
                        snprintf(name, sizeof(name), "%s-%d-%s-%s-%s", viewProjectionName(sc.camera), view, pathNames[path], materials[mi].name, lightNames[li]);
                        for (char *c = name; *c; c++) if ((*c == ' ') || (*c == '=')) *c = '_';
                        LitError e = viewCheckPlane(&sc, path == 3, name, 2.0, 0.25);
                        printf("    %-8s %-6s %-24s %-18s %-12s %6.0f %8.4f %7d\n", view? "oblique" : "head-on", viewProjectionName(sc.camera), pathNames[path],
                               materials[mi].name, lightNames[li], e.max, e.mean, e.pixels);
                        worst[proj] = fmax(worst[proj], e.max); worstMean[proj] = fmax(worstMean[proj], e.mean);
                    }
    printf("    worst: perspective max %.0f mean %.4f /255; orthographic max %.0f mean %.4f /255\n", worst[0], worstMean[0], worst[1], worstMean[1]);
}

// Fog under an orthographic camera: distance along the view axis from the camera's plane (a
// perspective camera keeps the distance to the eye), forward and deferred
static void test_view_orthographic_fog_runs_along_the_view_axis(void)
{
    const RblFog fogs[3] = { { RBL_FOG_LINEAR, { 120, 130, 150, 255 }, 2.0f, 9.0f, 0.0f }, { RBL_FOG_EXP, { 120, 130, 150, 255 }, 0.0f, 0.0f, 0.2f },
                             { RBL_FOG_EXP2, { 120, 130, 150, 255 }, 0.0f, 0.0f, 0.15f } };
    for (int proj = 0; proj < 2; proj++)
        for (int deferred = 0; deferred < (rtGlsl3()? 2 : 1); deferred++)
            for (int f = 0; f < 3; f++)
            {
                LitScene sc = litScene(RBL_BRDF_GGX);
                sc.values.roughness = 0.4f;
                sc.lights[0] = litPoint((Vector3){ 0.4f, 0.3f, 1.0f }, 2.0f, 6.0f);
                sc.count = 1;
                Camera3D ortho = viewOrtho((Vector3){ 0.0f, -6.0f, 3.0f }, (Vector3){ 0.0f, 2.0f, 0.0f }, 4.0f);
                sc.camera = proj? ortho : viewPerspective(ortho);
                sc.fog = fogs[f];
                char name[64];
                snprintf(name, sizeof(name), "%s-%s-fog%d", viewProjectionName(sc.camera), deferred? "deferred" : "forward", fogs[f].mode);
                LitError e = viewCheckPlane(&sc, deferred != 0, name, 2.0, 0.25);
                printf("    %s %-8s fog mode %d: max %.0f mean %.4f /255 over %d pixels, reference %.1f..%.1f\n", viewProjectionName(sc.camera),
                       deferred? "deferred" : "forward", fogs[f].mode, e.max, e.mean, e.pixels, e.refMin, e.refMax);
            }
}

// A sphere Model (raylib's GenMeshSphere) through RblDrawModel, raylib's own DrawModel and the
// G-buffer, against the reference interpolating its vertex normals, orthographic and perspective
static void test_view_orthographic_sphere_model_matches_the_double_reference(void)
{
    Mesh mesh = GenMeshSphere(VIEW_SPHERE_RADIUS, 32, 32);
    Model model = LoadModelFromMesh(mesh);
    ViewMesh ref = viewMeshOf(model.meshes[0], d3f(viewSpherePosition));
    struct { const char *name; int brdf; float shininess, roughness, metalness; bool forwardOnly; } materials[5] = {
        { "blinn-phong n=48", RBL_BRDF_BLINN_PHONG, 48.0f, 0, 0, false }, { "blinn-phong n=256", RBL_BRDF_BLINN_PHONG, 256.0f, 0, 0, true },
        { "ggx r=0.15 m=0", RBL_BRDF_GGX, 0, 0.15f, 0, true }, { "ggx r=0.3 m=1", RBL_BRDF_GGX, 0, 0.3f, 1, true }, { "ggx r=0.5 m=0", RBL_BRDF_GGX, 0, 0.5f, 0, false },
    };
    const char *pathNames[3] = { "RblDrawModel", "DrawModel", "deferred" };
    const Camera3D ortho = viewOrtho((Vector3){ 1.2f, 1.0f, 3.5f }, (Vector3){ 0.2f, -0.1f, 0.0f }, 2.6f);
    double worst[2] = { 0.0, 0.0 }, worstMean[2] = { 0.0, 0.0 };
    for (int proj = 0; proj < 2; proj++)
        for (int path = 0; path < 3; path++)
            for (int mi = 0; mi < 5; mi++)
            {
                if ((path == 2) && materials[mi].forwardOnly) continue;     // 12+12-bit G-buffer normals: moderate highlights only
                if ((path == 2) && !rtGlsl3()) continue;                    // no G-buffer on ES 2 / GL 2.1
                ViewSphere vs;
                memset(&vs, 0, sizeof(vs));
                vs.camera = proj? ortho : viewPerspective(ortho);
                vs.desc.shading.brdf = materials[mi].brdf;
                vs.values.shininess = materials[mi].shininess;
                vs.values.roughness = materials[mi].roughness;
                vs.values.metalness = materials[mi].metalness;
                vs.lights[0] = litPoint((Vector3){ 1.6f, 1.4f, 2.4f }, 6.0f, 10.0f);
                vs.lights[1] = litDirectional((Vector3){ 0.5f, -0.3f, -1.0f }, 0.8f);
                vs.lights[2] = litSpot((Vector3){ -1.5f, 1.5f, 2.5f }, (Vector3){ 0.6f, -0.6f, -1.0f }, 15.0f, 30.0f, 8.0f);
                vs.count = 3;
                vs.albedo = (Color){ 200, 160, 120, 255 };
                vs.ambient = (Color){ 25, 25, 30, 255 };
                bool ok = false;
                Image img = viewRenderSphere(&vs, &model, path, &ok);
                ViewError e = viewCompareSphere(&vs, &ref, img);
                printf("    %s %-13s %-18s max %3.0f mean %.4f /255 over %d pixels\n", viewProjectionName(vs.camera), pathNames[path], materials[mi].name, e.max, e.mean, e.pixels);
                RT_CHECK(ok, "%s %s: render refused", viewProjectionName(vs.camera), pathNames[path]);
                RT_CHECK(e.pixels > 2000, "%s %s %s: only %d pixels compared", viewProjectionName(vs.camera), pathNames[path], materials[mi].name, e.pixels);
                RT_CHECK(e.max <= 2.0 && e.mean <= 0.25, "%s %s %s: error max %.0f mean %.3f /255 (allowed 2, 0.25)", viewProjectionName(vs.camera), pathNames[path], materials[mi].name, e.max, e.mean);
                if (rtFailuresInCurrentTest() > 0)
                {
                    char tag[96];
                    snprintf(tag, sizeof(tag), "%s-%s-%d", viewProjectionName(vs.camera), pathNames[path], mi);
                    rtSaveImage(img, tag);
                }
                worst[proj] = fmax(worst[proj], e.max); worstMean[proj] = fmax(worstMean[proj], e.mean);
                UnloadImage(img);
            }
    printf("    worst: perspective max %.0f mean %.4f /255; orthographic max %.0f mean %.4f /255\n", worst[0], worstMean[0], worst[1], worstMean[1]);
    viewMeshFree(&ref);
    UnloadModel(model);
}

// ---- two-sided cards -----------------------------------------------------------------------------
// A fixed card (facing +Z) seen from in front or behind, lit from the viewer's side or the far side,
// with a flat or tilted normal map, forward (immediate, batched, instanced) and deferred (immediate,
// instanced), perspective and orthographic. The reference (litSurface) shades the side the viewer
// sees: from behind the normal flips, the map's tangent components stay (the card's mirror image).
static void test_view_card_seen_from_behind_is_lit_on_the_side_the_viewer_sees(void)
{
    const char *pathNames[5] = { "immediate", "batched", "instanced", "deferred immediate", "deferred instanced" };
    double worst[2] = { 0.0, 0.0 }, worstMean[2] = { 0.0, 0.0 };
    int uncovered = 0;
    for (int path = 0; path < (rtGlsl3()? 5 : 2); path++)     // instanced and deferred paths: GLSL 3 contexts
        for (int proj = 0; proj < 2; proj++)
            for (int behind = 0; behind < 2; behind++)
                for (int far = 0; far < 2; far++)
                    for (int tilted = 0; tilted < 2; tilted++)
                    {
                        bool deferred = path >= 3;
                        LitScene sc = litScene(RBL_BRDF_GGX);
                        sc.values.roughness = deferred? 0.5f : 0.35f;
                        sc.path = (path == 1)? LIT_PATH_BATCHED : (((path == 2) || (path == 4))? LIT_PATH_INSTANCED : LIT_PATH_IMMEDIATE);
                        float z = behind? -1.0f : 1.0f;                     // the viewer's side of the card
                        Camera3D ortho = viewOrtho((Vector3){ 0.4f, 0.3f, 4.0f*z }, (Vector3){ 0.0f, 0.0f, 0.0f }, 5.0f);
                        sc.camera = proj? ortho : viewPerspective(ortho);
                        sc.lights[0] = litPoint((Vector3){ 0.5f, 0.4f, (far? -1.2f : 1.2f)*z }, 2.0f, 6.0f);
                        sc.lights[1] = litDirectional((Vector3){ -0.3f, -0.2f, (far? 1.0f : -1.0f)*z }, 0.5f);
                        sc.count = 2;
                        sc.normalMap = true;
                        sc.normal = tilted? normalTexel(0.5f, 0.2f, 0.843f) : normalTexel(0.0f, 0.0f, 1.0f);
                        char name[128];
                        snprintf(name, sizeof(name), "%s-%s-%s-%s-%s", pathNames[path], viewProjectionName(sc.camera), behind? "behind" : "front",
                                 far? "far-light" : "near-light", tilted? "tilted" : "flat");
                        for (char *c = name; *c; c++) if (*c == ' ') *c = '_';
                        Image img;
                        bool ok = true;
                        if (deferred) img = viewRenderDeferredPlane(&sc, &ok);
                        else { LitRender r = litRender(&sc, 0); img = ImageCopy(r.image); ok = r.loaded; litRenderUnload(&r); }
                        int blank = 0;
                        for (int y = 0; y < LIT_TARGET; y++) for (int x = 0; x < LIT_TARGET; x++) blank += (rtPixel(img, x, y).a == 0);
                        LitError e = litCompare(&sc, img);
                        uncovered += blank;
                        RT_CHECK(ok, "%s: render refused", name);
                        RT_CHECK(blank == 0, "%s: %d pixels not drawn (culled?)", name, blank);
                        RT_CHECK(e.pixels > LIT_TARGET*LIT_TARGET/2, "%s: only %d pixels compared", name, e.pixels);
                        RT_CHECK(e.max <= 2.0 && e.mean <= 0.25, "%s: error max %.0f mean %.3f /255 (allowed 2, 0.25)", name, e.max, e.mean);
                        if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, name);
                        printf("    %-19s %s %-6s %-10s %-6s max %3.0f mean %7.4f /255, reference %5.1f..%5.1f\n", pathNames[path], viewProjectionName(sc.camera),
                               behind? "behind" : "front", far? "far light" : "near light", tilted? "tilted" : "flat", e.max, e.mean, e.refMin, e.refMax);
                        worst[behind] = fmax(worst[behind], e.max); worstMean[behind] = fmax(worstMean[behind], e.mean);
                        UnloadImage(img);
                    }
    printf("    worst: front max %.0f mean %.4f /255; behind max %.0f mean %.4f /255; %d pixels not drawn\n", worst[0], worstMean[0], worst[1], worstMean[1], uncovered);
}

// Without the reference's rule: seen from behind, the far side's light changes nothing (the image is
// the ambient-only one) and the viewer's side's light brightens it; a normal map tilted toward +U
// (world +X) is brighter lit from +X than from -X, from either side (a full negation of the normal
// from behind would light the -X side instead)
static void test_view_card_from_behind_far_light_adds_nothing_and_tilt_keeps_its_side(void)
{
    // Camera z (the viewer's side), light (0 none, 1 point, 2 directional) and where it is, map tilted toward +U
    struct { float eyeZ; int light; Vector3 at; bool tilted; } cases[7] = {
        { -4.0f, 0, { 0.0f, 0.0f, 0.0f }, false },                          // 0 behind: ambient only
        { -4.0f, 1, { 0.2f, 0.1f, 1.5f }, false },                          // 1 behind, point on the far side
        { -4.0f, 1, { 0.2f, 0.1f, -1.5f }, false },                         // 2 behind, point on the viewer's side
        { -4.0f, 2, { -1.0f, 0.0f, 0.5f }, true },                          // 3 behind, from +X on the viewer's side (direction of travel)
        { -4.0f, 2, { 1.0f, 0.0f, 0.5f }, true },                           // 4 behind, from -X
        { 4.0f, 2, { -1.0f, 0.0f, -0.5f }, true },                          // 5 front, from +X
        { 4.0f, 2, { 1.0f, 0.0f, -0.5f }, true },                           // 6 front, from -X
    };
    for (int deferred = 0; deferred < (rtGlsl3()? 2 : 1); deferred++)
    {
        double level[7];
        for (int k = 0; k < 7; k++)
        {
            LitScene sc = litScene(RBL_BRDF_LAMBERT);
            sc.normalMap = true;
            sc.normal = cases[k].tilted? normalTexel(0.6f, 0.0f, 0.8f) : normalTexel(0.0f, 0.0f, 1.0f);
            sc.camera = litCamera((Vector3){ 0.0f, 0.0f, cases[k].eyeZ }, (Vector3){ 0.0f, 0.0f, 0.0f });
            if (cases[k].light == 1) sc.lights[0] = litPoint(cases[k].at, 2.0f, 0.0f);
            if (cases[k].light == 2) sc.lights[0] = litDirectional(cases[k].at, 1.0f);
            sc.count = (cases[k].light > 0)? 1 : 0;
            bool ok = true;
            Image img;
            if (deferred) img = viewRenderDeferredPlane(&sc, &ok);
            else { LitRender r = litRender(&sc, 0); img = ImageCopy(r.image); ok = r.loaded; litRenderUnload(&r); }
            RT_CHECK(ok, "render %d refused", k);
            double sum = 0.0;
            for (int y = 0; y < LIT_TARGET; y++) for (int x = 0; x < LIT_TARGET; x++) { Color c = rtPixel(img, x, y); sum += c.r + c.g + c.b; }
            level[k] = sum/(3.0*LIT_TARGET*LIT_TARGET);
            if (rtFailuresInCurrentTest() > 0) { char tag[32]; snprintf(tag, sizeof(tag), "%s-%d", deferred? "deferred" : "forward", k); rtSaveImage(img, tag); }
            UnloadImage(img);
        }
        const char *how = deferred? "deferred" : "forward";
        printf("    %s, seen from behind: mean level ambient only %.2f, far-side light %.2f, viewer-side light %.2f /255; tilted toward +U, lit from +X / -X: front %.2f / %.2f, behind %.2f / %.2f\n",
               how, level[0], level[1], level[2], level[5], level[6], level[3], level[4]);
        RT_CHECK(fabs(level[1] - level[0]) < 0.01, "%s: a light on the far side changed the card seen from behind (%.2f vs ambient %.2f)", how, level[1], level[0]);
        RT_CHECK(level[2] > level[0] + 40.0, "%s: a light on the viewer's side left the card seen from behind near ambient (%.2f vs %.2f)", how, level[2], level[0]);
        RT_CHECK(level[5] > level[6] + 40.0, "%s front: map tilted toward +U not brighter lit from +X (%.2f vs %.2f)", how, level[5], level[6]);
        RT_CHECK(level[3] > level[4] + 40.0, "%s behind: map tilted toward +U not brighter lit from +X (%.2f vs %.2f)", how, level[3], level[4]);
    }
}

// Face culling: only a draw that shows the camera a quad's back turns it off, for itself, and turns it
// back on (raylib's default); a draw of front faces leaves the caller's state alone (on or off), and
// inside a shadow pass it stays off until RblEndShadowMap
static bool viewCullingEnabled(void)
{
    unsigned char (*isEnabled)(unsigned int) = NULL;
    void *p = rtGlProc("glIsEnabled");
    if (p == NULL) return false;
    memcpy(&isEnabled, &p, sizeof(p));
    return isEnabled(0x0B44) != 0;      // GL_CULL_FACE
}

static void test_view_culling_is_off_only_for_draws_that_show_a_back_and_restored(void)
{
    LitScene sc = litScene(RBL_BRDF_LAMBERT);
    sc.lights[0] = litPoint((Vector3){ 0.2f, 0.1f, -1.5f }, 2.0f, 0.0f);
    sc.count = 1;
    RblScene scene = litSceneOf(&sc);
    RT_CHECK(RblSetScene(&scene), "scene rejected");
    RblLitShaderDesc desc = litProgramDesc(&sc, 0);
    Shader plain = RblLoadLitShader(desc);
    desc.instanced = true;
    Shader inst = RblLoadLitShader(desc);
    Material m = LoadMaterialDefault();
    RblBatch batch = RblLoadBatch(4);
    RblInstanceBuffer ib = RblLoadInstanceBuffer(4);
    const char *pathNames[3] = { "immediate", "batched", "instanced" };
    for (int path = 0; path < (rtGlsl3()? 3 : 2); path++)     // instanced: GLSL 3 contexts
        for (int behind = 0; behind < 2; behind++)
            for (int callerOn = 0; callerOn < 2; callerOn++)
            {
                Camera3D cam = litCamera((Vector3){ 0.3f, 0.2f, behind? -4.0f : 4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f });
                RblBillboard b = litPlane();
                m.shader = (path == 2)? inst : plain;
                RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
                BeginTextureMode(rt);
                ClearBackground(BLANK);
                BeginMode3D(cam);
                if (callerOn) rlEnableBackfaceCulling(); else rlDisableBackfaceCulling();
                if (path == 0) RblDrawBillboard(cam, m, b);
                else if (path == 1) { RblBeginBatch(&batch, cam); RblBatchAdd(&batch, m, &b); RblEndBatch(&batch); }
                else
                {
                    RblInstance in;
                    memset(&in, 0, sizeof(in));
                    in.size = b.size; in.origin = b.origin;
                    RblInstancedDesc idesc;
                    memset(&idesc, 0, sizeof(idesc));
                    idesc.facing = RBL_FACING_FIXED; idesc.axis = b.axis; idesc.up = b.up;
                    RblDrawInstanced(&ib, cam, m, idesc, &in, 1);
                }
                bool after = viewCullingEnabled();
                EndMode3D();
                EndTextureMode();
                Image img = rtReadTarget(rt);
                UnloadRenderTexture(rt);
                Color c = rtPixel(img, LIT_TARGET/2, LIT_TARGET/2);
                UnloadImage(img);
                // A front view leaves the caller's state; a back view is drawn and leaves culling on
                bool want = behind? true : (callerOn != 0);
                printf("    %-9s %-6s caller culling %-3s: drawn %d, culling after %s\n", pathNames[path], behind? "behind" : "front", callerOn? "on" : "off", c.a != 0, after? "on" : "off");
                RT_CHECK(c.a == 255, "%s %s (caller culling %d): the card was not drawn", pathNames[path], behind? "behind" : "front", callerOn);
                RT_CHECK(after == want, "%s %s (caller culling %d): culling %d after the draw (expected %d)", pathNames[path], behind? "behind" : "front", callerOn, after, want);
            }
    rlEnableBackfaceCulling();

    // Inside a shadow pass culling is off for every caster, and a card seen from behind leaves it off
    RblLight sun = litDirectional((Vector3){ -0.2f, -0.3f, -1.0f }, 1.0f);
    RblScene shadowScene;
    memset(&shadowScene, 0, sizeof(shadowScene));
    shadowScene.lights = &sun; shadowScene.lightCount = 1;
    RblShadowDesc sdesc;
    memset(&sdesc, 0, sizeof(sdesc));
    sdesc.size = 64;
    RblShadowMap map = RblLoadShadowMap(sdesc);
    RT_CHECK(RblBeginShadowMap(&map, &shadowScene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 4.0f), "shadow pass refused");
    Camera3D back = litCamera((Vector3){ 0.3f, 0.2f, -4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f });
    m.shader = plain;
    RblBillboard card = litPlane();
    card.size = (Vector2){ 2.0f, 2.0f }; card.origin = (Vector2){ 1.0f, 1.0f };
    RblBeginBatch(&batch, back); RblBatchAdd(&batch, m, &card); RblEndBatch(&batch);
    bool inPass = viewCullingEnabled();
    RblEndShadowMap(&map);
    RT_CHECK(!inPass, "a card seen from behind turned culling back on inside the shadow pass");
    RblUnloadShadowMap(&map);
    RblUnloadInstanceBuffer(&ib);
    RblUnloadBatch(&batch);
    MemFree(m.maps);
    RblUnloadLitShader(&plain); RblUnloadLitShader(&inst);
}

// A card seen from behind receives the shadow map of a light on the viewer's side: lit without
// self-shadowing (the lookup's normal offset and plane use the flipped normal), and darkened where a
// smaller card between the light and it (drawn only into the map) blocks the light; forward and
// deferred, perspective and orthographic
static Image viewRenderShadowedCard(const LitScene *sc, bool deferred, bool *ok)
{
    RblLitShaderDesc desc = litProgramDesc(sc, 0);
    desc.shading.shadowMaps = 1;
    RblGBufferDesc gdesc = defGBufferDesc(&desc, LIT_TARGET, LIT_TARGET);
    desc.deferred = deferred;
    Shader lit = RblLoadLitShader(desc);
    RblShadowDesc sdesc;
    memset(&sdesc, 0, sizeof(sdesc));
    sdesc.size = 1024;
    RblShadowMap map = RblLoadShadowMap(sdesc);
    Texture2D albedo = solidTexture(sc->albedo);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    rtSetMaterialValues(&m, sc->values);
    RblScene scene = litSceneOf(sc);
    *ok = RblIsLitShaderValid(lit) && RblIsShadowMapValid(map) && RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 5.0f);
    if (*ok)
    {
        RblBillboard card = litSceneBillboard(sc), blocker = card;
        blocker.position = (Vector3){ 0.0f, 0.0f, -1.0f };
        blocker.size = (Vector2){ 1.0f, 1.0f }; blocker.origin = (Vector2){ 0.5f, 0.5f };
        RblBatch batch = RblLoadBatch(4);
        RblBeginBatch(&batch, sc->camera);
        RblBatchAdd(&batch, m, &card);
        RblBatchAdd(&batch, m, &blocker);
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
        RblEndShadowMap(&map);
        scene.shadowMaps = &map;
        scene.shadowMapCount = 1;
        *ok = RblSetScene(&scene);
    }
    RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
    if (!deferred)
    {
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        BeginMode3D(sc->camera);
        litDrawPlane(sc, m);
        EndMode3D();
        EndTextureMode();
    }
    else
    {
        RblGBuffer g = RblLoadGBuffer(gdesc);
        if (*ok && RblBeginGBuffer(&g, sc->camera))
        {
            litDrawPlane(sc, m);
            RblEndGBuffer(&g);
            *ok = RblDrawDeferredLights(&g);
        }
        else *ok = false;
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        if (*ok) RblResolveGBuffer(&g);
        EndTextureMode();
        RblUnloadGBuffer(&g);
    }
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    UnloadTexture(albedo);
    MemFree(m.maps);
    RblUnloadShadowMap(&map);
    RblUnloadLitShader(&lit);
    return img;
}

static void test_view_card_seen_from_behind_receives_shadows_on_its_lit_side(void)
{
    const Vector3 sunDirection = { 0.3f, 0.2f, 1.0f };         // travels toward +Z: comes from the -Z side
    for (int deferred = 0; deferred < (rtGlsl3()? 2 : 1); deferred++)     // G-buffer: GLSL 3 contexts
        for (int proj = 0; proj < 2; proj++)
        {
            LitScene sc = litScene(RBL_BRDF_LAMBERT);
            sc.lights[0] = litDirectional(sunDirection, 1.0f);
            sc.count = 1;
            Camera3D ortho = viewOrtho((Vector3){ -0.5f, 0.4f, -4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, 5.0f);
            sc.camera = proj? ortho : viewPerspective(ortho);
            bool ok = false;
            Image img = viewRenderShadowedCard(&sc, deferred != 0, &ok);
            // The blocker (1 x 1 at z = -1) shadows the square centred where the light's ray through its
            // centre meets z = 0; pixels farther than 0.25 from that square's edge are compared
            D3 d = dNorm(d3f(sunDirection));
            D3 centre = d3(d.x/d.z, d.y/d.z, 0.0);
            RefParams rp = litShading(&sc);
            int lit = 0, shadowed = 0;
            double litMax = 0.0, shadowMax = 0.0;
            for (int py = 1; py < LIT_TARGET - 1; py++)
                for (int px = 1; px < LIT_TARGET - 1; px++)
                {
                    D3 p;
                    if (!refPixelOnPlane(sc.camera, LIT_TARGET, LIT_TARGET, px, py, d3(0, 0, 0), d3(0, 0, 1), &p)) continue;
                    double edge = fmax(fabs(p.x - centre.x), fabs(p.y - centre.y)) - 0.5;     // signed distance to the square
                    if (fabs(edge) < 0.25) continue;
                    RefSurface s = litSurface(&sc, p);
                    RefRgb ref = refFinishAt(&rp, refShadeView(&rp, sc.lights, (edge < 0.0)? 0 : 1, &sc.env, &s, refViewVector(sc.camera, p)), refViewDistance(sc.camera, p));
                    Color c = rtPixel(img, px, py);
                    const double got[3] = { c.r, c.g, c.b }, want[3] = { ref.r*255.0, ref.g*255.0, ref.b*255.0 };
                    double err = 0.0;
                    for (int ch = 0; ch < 3; ch++) err = fmax(err, fabs(got[ch] - floor(want[ch] + 0.5)));
                    if (edge < 0.0) { shadowed++; shadowMax = fmax(shadowMax, err); } else { lit++; litMax = fmax(litMax, err); }
                }
            const char *name = deferred? "deferred" : "forward";
            printf("    %-8s %s, card seen from behind: lit side max %.0f/255 over %d pixels (no self-shadowing), blocker's shadow max %.0f/255 over %d pixels\n",
                   name, viewProjectionName(sc.camera), litMax, lit, shadowMax, shadowed);
            RT_CHECK(ok, "%s %s: render refused", name, viewProjectionName(sc.camera));
            RT_CHECK(lit > 2000 && shadowed > 50, "%s %s: %d lit and %d shadowed pixels compared", name, viewProjectionName(sc.camera), lit, shadowed);
            RT_CHECK(litMax <= 2.0, "%s %s: the lit back side differs from the unshadowed reference by %.0f/255 (self-shadowing?)", name, viewProjectionName(sc.camera), litMax);
            RT_CHECK(shadowMax <= 2.0, "%s %s: the blocker's shadow differs from the ambient-only reference by %.0f/255", name, viewProjectionName(sc.camera), shadowMax);
            if (rtFailuresInCurrentTest() > 0) { char tag[32]; snprintf(tag, sizeof(tag), "%s-%s", name, viewProjectionName(sc.camera)); rtSaveImage(img, tag); }
            UnloadImage(img);
        }
}

// A raylib Model drawn without culling (an open mesh: raylib's GenMeshPlane, facing +Y) seen from
// below is two-sided like a card: lit by a light below it, untouched by one above it
static void test_view_open_model_seen_from_below_is_lit_on_the_side_seen(void)
{
    Mesh mesh = GenMeshPlane(6.0f, 6.0f, 1, 1);
    Texture2D albedo = solidTexture((Color){ 200, 160, 120, 255 });
    for (int deferred = 0; deferred < (rtGlsl3()? 2 : 1); deferred++)     // G-buffer: GLSL 3 contexts
    {
        double level[3];
        for (int k = 0; k < 3; k++)        // ambient only, light above (far side), light below (viewer's side)
        {
            RblLight light = litPoint((Vector3){ 0.3f, (k == 1)? 1.5f : -1.5f, 0.2f }, 2.0f, 0.0f);
            RblLitShaderDesc desc;
            memset(&desc, 0, sizeof(desc));
            desc.maxLights = 1;
            RblGBuffer g = RblLoadGBuffer(defGBufferDesc(&desc, LIT_TARGET, LIT_TARGET));
            desc.deferred = deferred;
            Shader lit = RblLoadLitShader(desc);
            RblScene scene;
            memset(&scene, 0, sizeof(scene));
            scene.lights = &light; scene.lightCount = (k > 0)? 1 : 0; scene.ambient = (Color){ 25, 25, 30, 255 };
            RT_CHECK(RblIsLitShaderValid(lit) && RblSetScene(&scene), "program or scene refused");
            Material m = LoadMaterialDefault();
            m.shader = lit;
            m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
            Camera3D cam = litCamera((Vector3){ 0.4f, -4.0f, 0.3f }, (Vector3){ 0.0f, 0.0f, 0.0f });
            cam.up = (Vector3){ 0.0f, 0.0f, 1.0f };
            RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
            if (deferred)
            {
                RT_CHECK(RblBeginGBuffer(&g, cam), "geometry pass refused");
                rlDisableBackfaceCulling();                 // the caller's choice for an open mesh
                RblDrawMesh(mesh, m, MatrixIdentity());
                rlEnableBackfaceCulling();
                RblEndGBuffer(&g);
                RT_CHECK(RblDrawDeferredLights(&g), "deferred lights refused");
                BeginTextureMode(rt); ClearBackground(BLANK); RblResolveGBuffer(&g); EndTextureMode();
            }
            else
            {
                BeginTextureMode(rt);
                ClearBackground(BLANK);
                BeginMode3D(cam);
                rlDisableBackfaceCulling();
                RblDrawMesh(mesh, m, MatrixIdentity());
                rlEnableBackfaceCulling();
                EndMode3D();
                EndTextureMode();
            }
            Image img = rtReadTarget(rt);
            UnloadRenderTexture(rt);
            double sum = 0.0;
            int covered = 0;
            for (int y = 0; y < LIT_TARGET; y++) for (int x = 0; x < LIT_TARGET; x++) { Color c = rtPixel(img, x, y); if (c.a == 0) continue; sum += c.r + c.g + c.b; covered++; }
            level[k] = (covered > 0)? sum/(3.0*covered) : 0.0;
            RT_CHECK(covered > LIT_TARGET*LIT_TARGET/2, "%s case %d: the plane covers %d pixels", deferred? "deferred" : "forward", k, covered);
            UnloadImage(img);
            MemFree(m.maps);
            RblUnloadLitShader(&lit);
            RblUnloadGBuffer(&g);
        }
        const char *how = deferred? "deferred" : "forward";
        printf("    %s, plane Model seen from below: mean level ambient only %.2f, light above %.2f, light below %.2f /255\n", how, level[0], level[1], level[2]);
        RT_CHECK(fabs(level[1] - level[0]) < 0.01, "%s: a light above the plane changed it seen from below (%.2f vs %.2f)", how, level[1], level[0]);
        RT_CHECK(level[2] > level[0] + 40.0, "%s: a light below left the plane seen from below near ambient (%.2f vs %.2f)", how, level[2], level[0]);
    }
    UnloadTexture(albedo);
    UnloadMesh(mesh);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_VIEW_TESTS \
    RT_TEST(test_view_orthographic_plane_on_every_path_matches_the_double_reference), \
    RT_TEST(test_view_orthographic_fog_runs_along_the_view_axis), \
    RT_TEST(test_view_orthographic_sphere_model_matches_the_double_reference), \
    RT_TEST(test_view_card_seen_from_behind_is_lit_on_the_side_the_viewer_sees), \
    RT_TEST(test_view_card_from_behind_far_light_adds_nothing_and_tilt_keeps_its_side), \
    RT_TEST(test_view_culling_is_off_only_for_draws_that_show_a_back_and_restored), \
    RT_TEST(test_view_card_seen_from_behind_receives_shadows_on_its_lit_side), \
    RT_TEST(test_view_open_model_seen_from_below_is_lit_on_the_side_seen)
