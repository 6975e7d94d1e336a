// Lights scattered over the floor a camera sees, shared by bench_deferred and bench_clustered (the
// same scene, so their rows compare). Needs raylib, harness.h (rtRandomRange) and the header first.
#ifndef RBL_BENCH_FLOOR_H
#define RBL_BENCH_FLOOR_H

// Where the screen pixel's ray meets the floor y = 0 (false: it misses)
static bool benchFloorHit(Camera3D camera, int width, int height, float x, float y, Vector2 *out)
{
    Ray r = GetScreenToWorldRayEx((Vector2){ x, y }, camera, width, height);
    if (!(r.direction.y < -1e-6f)) return false;
    float t = -r.position.y/r.direction.y;
    *out = (Vector2){ r.position.x + t*r.direction.x, r.position.z + t*r.direction.z };
    return true;
}

static float benchCross2(Vector2 a, Vector2 b, Vector2 p) { return (b.x - a.x)*(p.y - a.y) - (b.y - a.y)*(p.x - a.x); }

// n point lights uniformly over the visible floor (the screen corners' floor quad; rejection
// sampling), range 0.3-0.8, 10-60% of the range above the floor, so every light reaches the floor;
// false when a screen corner misses the floor
static bool benchScatterFloorLights(Camera3D camera, int width, int height, RblLight *lights, int n)
{
    Vector2 q[4];
    const float corner[4][2] = { { 0.0f, 0.0f }, { (float)width, 0.0f }, { (float)width, (float)height }, { 0.0f, (float)height } };
    for (int k = 0; k < 4; k++) if (!benchFloorHit(camera, width, height, corner[k][0], corner[k][1], &q[k])) return false;
    float lo[2] = { q[0].x, q[0].y }, hi[2] = { q[0].x, q[0].y };
    for (int k = 1; k < 4; k++)
    {
        lo[0] = fminf(lo[0], q[k].x); hi[0] = fmaxf(hi[0], q[k].x);
        lo[1] = fminf(lo[1], q[k].y); hi[1] = fmaxf(hi[1], q[k].y);
    }
    float orient = benchCross2(q[0], q[1], q[2]);
    unsigned int seed = 20240601u;
    for (int i = 0; i < n; )
    {
        Vector2 p = { rtRandomRange(&seed, lo[0], hi[0]), rtRandomRange(&seed, lo[1], hi[1]) };
        bool inside = true;
        for (int k = 0; k < 4; k++) inside = inside && (benchCross2(q[k], q[(k + 1)%4], p)*orient >= 0.0f);
        if (!inside) continue;
        RblLight l;
        memset(&l, 0, sizeof(l));
        l.type = RBL_LIGHT_POINT;
        l.range = rtRandomRange(&seed, 0.3f, 0.8f);
        l.position = (Vector3){ p.x, l.range*rtRandomRange(&seed, 0.1f, 0.6f), p.y };
        l.color = (Color){ (unsigned char)(96 + rtRandom(&seed)%160), (unsigned char)(96 + rtRandom(&seed)%160), (unsigned char)(96 + rtRandom(&seed)%160), 255 };
        l.intensity = rtRandomRange(&seed, 0.01f, 0.04f);
        lights[i++] = l;
    }
    return true;
}

#endif // RBL_BENCH_FLOOR_H
