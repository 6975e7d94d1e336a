// Double-precision reference of the forward shading equations, written from their definitions
// (Filament's GGX / Smith height-correlated / Schlick; normalised Blinn-Phong; UE4 windowed falloff;
// smoothstep spot cone; Reinhard; Narkowicz ACES fit; IEC 61966-2-1 sRGB), not from the shader code:
// it takes the same RblLight values a user passes to the header, plus RefParams (the program's
// features, the material's values and the scene's settings in one place), and applies the
// documented defaults itself. Shared by the lighting tests and the lighting benchmark.
#ifndef RBL_TEST_LIGHTING_REFERENCE_H
#define RBL_TEST_LIGHTING_REFERENCE_H

#include "reference.h"

typedef struct { double r, g, b; } RefRgb;
static inline RefRgb refRgb(double r, double g, double b) { RefRgb c = { r, g, b }; return c; }
static inline RefRgb refLinear(Color c) { return refRgb(srgbDecode(c.r/255.0), srgbDecode(c.g/255.0), srgbDecode(c.b/255.0)); }
static inline RefRgb refAddScaled(RefRgb a, RefRgb b, double s) { return refRgb(a.r + b.r*s, a.g + b.g*s, a.b + b.b*s); }
static inline RefRgb refMul(RefRgb a, RefRgb b) { return refRgb(a.r*b.r, a.g*b.g, a.b*b.b); }
static inline double refClamp(double x, double lo, double hi) { return fmin(fmax(x, lo), hi); }

// What shades a point besides its lights and surface: compiled features (brdf, tonemap, gamma,
// output), the material's values (raylib Material fields in 1.0) and the scene's fog and exposure,
// under their 0.3 names; zero means the header's documented default
typedef struct RefParams {
    int brdf;                   // RblBrdf
    float specular;             // Blinn-Phong intensity (MATERIAL_MAP_SPECULAR.value)
    float shininess;            // Blinn-Phong exponent (MATERIAL_MAP_NORMAL.value)
    Color specularColor;        // MATERIAL_MAP_SPECULAR.color
    float roughness;            // GGX (MATERIAL_MAP_ROUGHNESS.value)
    float metalness;            // GGX (MATERIAL_MAP_METALNESS.value)
    Color emissiveColor;        // MATERIAL_MAP_EMISSION.color
    float emissiveIntensity;    // MATERIAL_MAP_EMISSION.value
    bool hemisphereAmbient;     // the scene has a ground colour
    RblFog fog;                 // the scene's fog (applied when the program compiled that mode)
    int tonemap;                // RblTonemap
    float exposure;             // the scene's exposure
    float gamma;                // display encoding (0 = sRGB)
    bool linearOutput;
    double transmission;        // share of a card's back irradiance let through (params[RBL_PARAM_TRANSMISSION] x (1 - thickness); 0 = none)
} RefParams;

// Environment of a shading point besides its lights
typedef struct RefEnvironment {
    Color ambient;              // flat ambient (RblSetLights), or the sky when hemispheric
    Color ground;               // hemispheric ground colour (RblSetHemisphereAmbient)
    D3 up;                      // hemispheric up
} RefEnvironment;

// Surface at one point: what the shader knows after decoding its maps
typedef struct RefSurface {
    D3 position, normal;        // world; normal unit
    RefRgb albedo;              // linear
    double specularMap;         // value of the specular/roughness map (< 0: no map)
    double occlusion;           // 1 without a map
} RefSurface;

// Irradiance one light delivers to point p on a surface facing it (NdotL not included), and the unit direction to it
static inline RefRgb refLightIncident(const RblLight *L, D3 p, D3 n, D3 *toLight)
{
    double attenuation = 1.0;
    D3 l;
    if (L->type == RBL_LIGHT_DIRECTIONAL)
    {
        l = dScale(dNorm(d3f(L->direction)), -1.0);
    }
    else
    {
        D3 v = dSub(d3f(L->position), p);
        double d = dLen(v);
        l = (d > 0.0)? dScale(v, 1.0/d) : n;        // a light on the surface lights it head-on
        double window = 1.0;
        if (L->range > 0.0f) { double x = d/L->range; window = refClamp(1.0 - x*x*x*x, 0.0, 1.0); window *= window; }
        double denom = d*d;
        if (L->falloff == RBL_FALLOFF_CLASSIC)
        {
            bool none = (L->constant == 0.0f) && (L->linear == 0.0f) && (L->quadratic == 0.0f);
            denom = none? 1.0 : (L->constant + L->linear*d + L->quadratic*d*d);
        }
        attenuation = window/fmax(denom, 1e-4);
        if (L->type == RBL_LIGHT_SPOT)
        {
            double outer = (L->outerAngle == 0.0f)? 30.0 : L->outerAngle;
            double cosInner = cos(L->innerAngle*PI/180.0), cosOuter = cos(outer*PI/180.0);
            double cosAngle = dDot(dScale(l, -1.0), dNorm(d3f(L->direction)));
            double t = refClamp((cosAngle - cosOuter)/fmax(cosInner - cosOuter, 1e-4), 0.0, 1.0);
            attenuation *= t*t*(3.0 - 2.0*t);
        }
    }
    *toLight = l;
    RefRgb c = refLinear(L->color);
    double s = L->intensity*attenuation;
    return refRgb(c.r*s, c.g*s, c.b*s);
}

// Irradiance delivered by one light to point p with normal n (NdotL included), and the unit direction to it
static inline RefRgb refLightIrradiance(const RblLight *L, D3 p, D3 n, D3 *toLight)
{
    RefRgb e = refLightIncident(L, p, n, toLight);
    double ndotl = dDot(n, *toLight);
    if (ndotl <= 0.0) return refRgb(0, 0, 0);
    return refRgb(e.r*ndotl, e.g*ndotl, e.b*ndotl);
}

// Light through a thin diffuse card (RblLitShaderDesc.transmission): of the irradiance E on its back
// (the light's incident irradiance x the back's cosine, wrapped by w = 1/4 so a light edge-on still
// shows through the rim) the share t leaves the front diffusely in the card's colour:
// L = albedo x t x E0 x clamp((w - N.L)/(1 + w), 0, 1), N the shading normal on the viewer's side
static inline RefRgb refTransmitted(const RefParams *d, const RefSurface *s, RefRgb incident, D3 l)
{
    const double w = 0.25;
    double back = refClamp((w - dDot(s->normal, l))/(1.0 + w), 0.0, 1.0)*d->transmission;
    return refRgb(s->albedo.r*incident.r*back, s->albedo.g*incident.g*back, s->albedo.b*incident.b*back);
}

// pi * BRDF for one channel set: diffuse + specular, given unit n, v, l
static inline RefRgb refBrdf(const RefParams *d, const RefSurface *s, D3 v, D3 l)
{
    D3 n = s->normal;
    if (d->brdf == RBL_BRDF_BLINN_PHONG)
    {
        double shininess = (d->shininess == 0.0f)? 32.0 : fmax(d->shininess, 1.0);
        double scale = (d->specular != 0.0f)? d->specular : ((s->specularMap >= 0.0)? 1.0 : 0.5);
        double intensity = scale*((s->specularMap >= 0.0)? s->specularMap : 1.0);
        Color sc = d->specularColor;
        RefRgb spec = ((sc.r | sc.g | sc.b | sc.a) == 0)? refRgb(1, 1, 1) : refLinear(sc);
        D3 hv = dAdd(l, v);
        D3 h = (dLen(hv) > 0.0)? dNorm(hv) : n;
        double k = intensity*(shininess + 8.0)/8.0*pow(fmax(dDot(n, h), 0.0), shininess);
        return refAddScaled(s->albedo, spec, k);
    }
    if (d->brdf == RBL_BRDF_GGX)
    {
        double perceptual = (s->specularMap >= 0.0)? s->specularMap : ((d->roughness == 0.0f)? 0.5 : d->roughness);
        perceptual = fmax(perceptual, 0.045);
        double a = perceptual*perceptual, a2 = a*a;
        double metal = d->metalness;
        D3 hv = dAdd(l, v);
        D3 h = (dLen(hv) > 0.0)? dNorm(hv) : n;
        double nh = refClamp(dDot(n, h), 0.0, 1.0);
        double q = nh*nh*(a2 - 1.0) + 1.0;
        double D = a2/(PI*q*q);
        double nv = fmax(dDot(n, v), 1e-4), nl = dDot(n, l);
        double V = 0.5/(nl*sqrt(nv*nv*(1.0 - a2) + a2) + nv*sqrt(nl*nl*(1.0 - a2) + a2));
        double fw = pow(1.0 - refClamp(dDot(l, h), 0.0, 1.0), 5.0);
        RefRgb f0 = refRgb(0.04 + (s->albedo.r - 0.04)*metal, 0.04 + (s->albedo.g - 0.04)*metal, 0.04 + (s->albedo.b - 0.04)*metal);
        RefRgb F = refRgb(f0.r + (1.0 - f0.r)*fw, f0.g + (1.0 - f0.g)*fw, f0.b + (1.0 - f0.b)*fw);
        RefRgb diffuse = refRgb(s->albedo.r*(1.0 - metal), s->albedo.g*(1.0 - metal), s->albedo.b*(1.0 - metal));
        return refAddScaled(diffuse, F, PI*D*V);
    }
    return s->albedo;
}

// Unit view vector at p (toward the viewer): perspective toward the eye; orthographic the camera's
// back direction (target toward position) everywhere, since every ray of the projection is parallel
static inline D3 refViewVector(Camera3D cam, D3 p)
{
    if (cam.projection == CAMERA_ORTHOGRAPHIC) return dNorm(dSub(d3f(cam.position), d3f(cam.target)));
    D3 toEye = dSub(d3f(cam.position), p);
    return (dLen(toEye) > 0.0)? dNorm(toEye) : d3(0, 0, 1);
}

// Fog distance of p: perspective the distance to the eye; orthographic the distance along the view
// axis from the camera's plane (the eye is a plane, not a point, under a parallel projection)
static inline double refViewDistance(Camera3D cam, D3 p)
{
    D3 eye = d3f(cam.position);
    if (cam.projection == CAMERA_ORTHOGRAPHIC) return fmax(dDot(dSub(eye, p), dNorm(dSub(eye, d3f(cam.target)))), 0.0);
    return dLen(dSub(p, eye));
}

// Linear radiance leaving the surface along the unit view vector v (ambient + direct + constant
// emission), before fog
static inline RefRgb refShadeView(const RefParams *d, const RblLight *lights, int count, const RefEnvironment *env,
                                  const RefSurface *s, D3 v)
{
    RefRgb ambient = refLinear(env->ambient);
    if (d->hemisphereAmbient)
    {
        double w = dDot(s->normal, dNorm(env->up))*0.5 + 0.5;
        RefRgb g = refLinear(env->ground);
        ambient = refRgb(g.r + (ambient.r - g.r)*w, g.g + (ambient.g - g.g)*w, g.b + (ambient.b - g.b)*w);
    }
    RefRgb reflectance = s->albedo;
    if (d->brdf == RBL_BRDF_GGX)
    {
        double m = d->metalness;
        reflectance = refRgb(s->albedo.r*(1.0 - m) + 0.04 + (s->albedo.r - 0.04)*m, s->albedo.g*(1.0 - m) + 0.04 + (s->albedo.g - 0.04)*m,
                             s->albedo.b*(1.0 - m) + 0.04 + (s->albedo.b - 0.04)*m);
    }
    RefRgb out = refMul(ambient, reflectance);
    out = refRgb(out.r*s->occlusion, out.g*s->occlusion, out.b*s->occlusion);
    for (int i = 0; i < count; i++)
    {
        D3 l;
        if (d->transmission > 0.0)
        {
            RefRgb incident = refLightIncident(&lights[i], s->position, s->normal, &l);
            out = refAddScaled(out, refTransmitted(d, s, incident, l), 1.0);
        }
        RefRgb e = refLightIrradiance(&lights[i], s->position, s->normal, &l);
        if ((e.r == 0.0) && (e.g == 0.0) && (e.b == 0.0)) continue;
        out = refAddScaled(out, refMul(e, refBrdf(d, s, v, l)), 1.0);
    }
    double ei = (d->emissiveIntensity == 0.0f)? 1.0 : d->emissiveIntensity;
    out = refAddScaled(out, refLinear(d->emissiveColor), ei);
    return out;
}

// The same seen from a point eye (perspective)
static inline RefRgb refShade(const RefParams *d, const RblLight *lights, int count, const RefEnvironment *env,
                              const RefSurface *s, D3 eye)
{
    D3 toEye = dSub(eye, s->position);
    D3 v = (dLen(toEye) > 0.0)? dNorm(toEye) : s->normal;
    return refShadeView(d, lights, count, env, s, v);
}

// Fog, half-float clamp, exposure, tonemap, display encoding: the value written to an 8-bit target, 0..1
static inline double refFinishChannel(const RefParams *d, double c, double fogColor, double distance)
{
    if (d->fog.mode != RBL_FOG_NONE)
    {
        double visible = 1.0;
        if (d->fog.mode == RBL_FOG_LINEAR) visible = refClamp((d->fog.end - distance)/(d->fog.end - d->fog.start), 0.0, 1.0);
        else if (d->fog.mode == RBL_FOG_EXP) visible = exp(-d->fog.density*distance);
        else visible = exp(-(d->fog.density*distance)*(d->fog.density*distance));
        c = fogColor + (c - fogColor)*visible;
    }
    c = refClamp(c, 0.0, 65504.0);
    c *= (d->exposure == 0.0f)? 1.0 : d->exposure;
    if (d->tonemap == RBL_TONEMAP_REINHARD) c = c/(1.0 + c);
    else if (d->tonemap == RBL_TONEMAP_ACES) { c = fmin(c, 65504.0); c = refClamp(c*(2.51*c + 0.03)/(c*(2.43*c + 0.59) + 0.14), 0.0, 1.0); }
    if (d->linearOutput) return fmin(c, 65504.0);
    if (d->gamma > 0.0f) return pow(refClamp(c, 0.0, 1.0), 1.0/d->gamma);
    return srgbEncode(c);
}

// The output of linear radiance c at fog distance `distance`
static inline RefRgb refFinishAt(const RefParams *d, RefRgb c, double distance)
{
    RefRgb fog = refLinear(d->fog.color);
    return refRgb(refFinishChannel(d, c.r, fog.r, distance), refFinishChannel(d, c.g, fog.g, distance), refFinishChannel(d, c.b, fog.b, distance));
}

static inline RefRgb refFinish(const RefParams *d, RefRgb c, D3 position, D3 eye) { return refFinishAt(d, c, dLen(dSub(position, eye))); }

// Ray through the centre of pixel (px, py) (row 0 at the top) of a width x height target, as raylib's
// BeginMode3D projects: perspective from the eye (fovy = vertical angle); orthographic parallel to the
// view axis from the camera's plane (fovy = view height in world units)
static inline void refPixelRay(Camera3D cam, int width, int height, int px, int py, D3 *origin, D3 *dir)
{
    D3 eye = d3f(cam.position), f = dNorm(dSub(d3f(cam.target), eye));
    D3 r = dNorm(dCross(f, d3f(cam.up))), u = dCross(r, f);
    double aspect = (double)width/height;
    double ndcX = ((px + 0.5)/width)*2.0 - 1.0, ndcY = 1.0 - ((py + 0.5)/height)*2.0;
    if (cam.projection == CAMERA_ORTHOGRAPHIC)
    {
        double top = cam.fovy*0.5;
        *origin = dAdd(eye, dAdd(dScale(r, ndcX*top*aspect), dScale(u, ndcY*top)));
        *dir = f;
        return;
    }
    double t = tan(cam.fovy*PI/360.0);
    *origin = eye;
    *dir = dAdd(f, dAdd(dScale(r, ndcX*t*aspect), dScale(u, ndcY*t)));
}

// World point seen through the centre of pixel (px, py) on the plane through p0 with normal n; false
// when the ray misses it or meets it nearer than raylib's near plane (RL_CULL_DISTANCE_NEAR, 0.05: the
// GPU clips it; the ray's view-axis component is 1, so s is the view depth)
static inline bool refPixelOnPlane(Camera3D cam, int width, int height, int px, int py, D3 p0, D3 n, D3 *hit)
{
    D3 origin, dir;
    refPixelRay(cam, width, height, px, py, &origin, &dir);
    double denom = dDot(dir, n);
    if (fabs(denom) < 1e-12) return false;
    double s = dDot(dSub(p0, origin), n)/denom;
    if (s < 0.05) return false;
    *hit = dAdd(origin, dScale(dir, s));
    return true;
}

// A triangle mesh as the rasterizer shades it: the point a pixel's centre sees on the nearest
// triangle, and the vertex normals interpolated there with that point's barycentrics (what
// perspective-correct interpolation gives; under a parallel projection they are the screen's)
typedef struct RefMesh { int triangles; D3 *p, *n; } RefMesh;      // 3 vertices per triangle

// The mesh's triangles (indexed or not) moved by offset; free with refMeshFree
static inline RefMesh refMeshOf(Mesh mesh, D3 offset)
{
    RefMesh r;
    r.triangles = mesh.triangleCount;
    r.p = (D3 *)malloc(sizeof(D3)*3*(size_t)r.triangles);
    r.n = (D3 *)malloc(sizeof(D3)*3*(size_t)r.triangles);
    for (int t = 0; t < r.triangles; t++)
        for (int k = 0; k < 3; k++)
        {
            int i = (mesh.indices != NULL)? mesh.indices[t*3 + k] : t*3 + k;
            r.p[t*3 + k] = dAdd(d3(mesh.vertices[i*3], mesh.vertices[i*3 + 1], mesh.vertices[i*3 + 2]), offset);
            r.n[t*3 + k] = d3(mesh.normals[i*3], mesh.normals[i*3 + 1], mesh.normals[i*3 + 2]);
        }
    return r;
}

static inline void refMeshFree(RefMesh *r) { free(r->p); free(r->n); r->p = r->n = NULL; r->triangles = 0; }

// Nearest front-facing hit of the ray o + s d (s > 0; Moller-Trumbore), its point and interpolated
// unit normal; false when it misses
static inline bool refMeshRay(const RefMesh *m, D3 o, D3 d, D3 *hit, D3 *normal)
{
    double best = INFINITY;
    for (int t = 0; t < m->triangles; t++)
    {
        D3 a = m->p[t*3], e1 = dSub(m->p[t*3 + 1], a), e2 = dSub(m->p[t*3 + 2], a);
        D3 q = dCross(d, e2);
        double det = dDot(e1, q);
        if (det <= 1e-300) continue;                 // back face or edge-on (culled)
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

#endif
