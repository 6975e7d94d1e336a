// The viewer (GPU, headless): orthographic cameras and two-sided cards, against the double reference.
// Orthographic: every ray is parallel, so the view vector is the camera's back direction everywhere
// (not eye - position) and fog runs along the view axis; a plane on every billboard path, a sphere
// Model (RblDrawModel and raylib's own DrawModel) and the G-buffer, each with a perspective control.
// Two-sided: a card seen from behind is shaded on the side the viewer sees (its mirror image through
// its plane) and is not culled, forward and deferred. Included by test_gpu_main.c after test_deferred.c.

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
    *ok = RblIsGBufferValid(&g) && RblIsLitShaderValid(geo) && RblSetScene(&scene);
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
    d.brdf = vs->desc.brdf;
    d.specular = vs->values.specular; d.shininess = vs->values.shininess; d.specularColor = vs->values.specularColor;
    d.roughness = vs->values.roughness; d.metalness = vs->values.metalness;
    d.fog = vs->fog; d.tonemap = vs->desc.tonemap;
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
    desc.lightFeatures = RblLightFeatures(vs->lights, vs->count);
    desc.fog = vs->fog.mode;
    RblGBuffer g;
    memset(&g, 0, sizeof(g));
    if (path == 2) { g = RblLoadGBuffer(defGBufferDesc(&desc, LIT_TARGET, LIT_TARGET)); desc.deferred = true; }
    Shader lit = RblLoadLitShader(desc);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = vs->lights; scene.lightCount = vs->count; scene.ambient = vs->ambient; scene.fog = vs->fog;
    *ok = RblIsLitShaderValid(lit) && RblSetScene(&scene) && ((path != 2) || RblIsGBufferValid(&g));
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
        for (int deferred = 0; deferred < 2; deferred++)
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
                ViewSphere vs;
                memset(&vs, 0, sizeof(vs));
                vs.camera = proj? ortho : viewPerspective(ortho);
                vs.desc.brdf = materials[mi].brdf;
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
