// Material maps specification (CPU only): normal encodings and their measured error, the height /
// luminance / occlusion generators, and RblPackMaterial (validation, layout, defaults, conversion,
// gutter dilation, mip chains). Included by test_cpu_main.c (one translation unit with the
// implementation, so the generators' unquantised normal rbl__heightNormal is reachable too).

#include <stdarg.h>

#define MAT_PI 3.14159265358979323846
#define MAT_DEG (180.0/MAT_PI)

// ---- helpers ------------------------------------------------------------------------------------
// Uniform sample of the z >= 0 hemisphere (z uniform in [0,1] is uniform in area), fixed seed
static Vector3 *hemisphereSample(int count, unsigned int seed)
{
    Vector3 *n = (Vector3 *)malloc((size_t)count*sizeof(Vector3));
    for (int i = 0; i < count; i++)
    {
        double z = (rtRandom(&seed) & 0xFFFFFF)/(double)0xFFFFFF;
        double phi = 2.0*MAT_PI*(rtRandom(&seed) & 0xFFFFFF)/(double)0xFFFFFF;
        double r = sqrt(1.0 - z*z);
        n[i] = (Vector3){ (float)(r*cos(phi)), (float)(r*sin(phi)), (float)z };
    }
    return n;
}

// Angle between two directions in degrees (double, any lengths; atan2 is exact near 0)
static double angleDeg(Vector3 a, Vector3 b)
{
    double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    double cx = ay*bz - az*by, cy = az*bx - ax*bz, cz = ax*by - ay*bx;
    return atan2(sqrt(cx*cx + cy*cy + cz*cz), ax*bx + ay*by + az*bz)*MAT_DEG;
}

static double lenOf(Vector3 v) { return sqrt((double)v.x*v.x + (double)v.y*v.y + (double)v.z*v.z); }

// Hemi-octahedral code by plain rounding (the baseline the precise encoder must never lose to),
// written independently from the header: p = (x,y)/(|x|+|y|+z), stored (p.x+p.y, p.x-p.y)*0.5+0.5
static void hemiOctRounded(Vector3 n, unsigned char out[3])
{
    double l = lenOf(n), x = n.x/l, y = n.y/l, z = n.z/l;
    double s = fabs(x) + fabs(y) + z, px = x/s, py = y/s;
    out[0] = (unsigned char)floor(((px + py)*0.5 + 0.5)*255.0 + 0.5);
    out[1] = (unsigned char)floor(((px - py)*0.5 + 0.5)*255.0 + 0.5);
    out[2] = 0;
}

// An image whose data raylib can free (UnloadImage)
static Image matImage(int w, int h, int format)
{
    Image img;
    memset(&img, 0, sizeof(img));
    img.data = MemAlloc((unsigned int)GetPixelDataSize(w, h, format));
    img.width = w;
    img.height = h;
    img.mipmaps = 1;
    img.format = format;
    return img;
}

static unsigned char *texel4(Image img, int x, int y) { return (unsigned char *)img.data + ((size_t)y*img.width + x)*4; }

// RGB8 normal map texel (c = n*0.5 + 0.5, rounded)
static void putNormal(Image img, int x, int y, Vector3 n)
{
    double l = lenOf(n);
    unsigned char *p = texel4(img, x, y);
    p[0] = (unsigned char)floor((n.x/l*0.5 + 0.5)*255.0 + 0.5);
    p[1] = (unsigned char)floor((n.y/l*0.5 + 0.5)*255.0 + 0.5);
    p[2] = (unsigned char)floor((n.z/l*0.5 + 0.5)*255.0 + 0.5);
    p[3] = 255;
}

// Byte offset of mip level `level` of an image of the given base size and bytes per texel (raylib's rule)
static size_t mipOffset(int w, int h, int bpp, int level, int *lw, int *lh)
{
    size_t offset = 0;
    for (int l = 0; l < level; l++)
    {
        offset += (size_t)w*h*bpp;
        w = (w > 1)? w/2 : 1;
        h = (h > 1)? h/2 : 1;
    }
    *lw = w; *lh = h;
    return offset;
}

// Warnings logged with the "RBL:" prefix while the counting logger is installed
static int matWarnings = 0;
static char matLastWarning[256] = "";
static void matCountingLog(int level, const char *text, va_list args)
{
    char buf[256];
    vsnprintf(buf, sizeof(buf), text, args);
    if ((level >= LOG_WARNING) && (strncmp(buf, "RBL:", 4) == 0)) { matWarnings++; snprintf(matLastWarning, sizeof(matLastWarning), "%s", buf); }
}

static RblMaterialSource sourceOf(Image albedo)
{
    RblMaterialSource s;
    memset(&s, 0, sizeof(s));
    s.albedo = albedo;
    return s;
}

// ---- encodings ----------------------------------------------------------------------------------
static void test_materials_encodings_round_trip_a_uniform_hemisphere_near_the_reference_errors(void)
{
    const int count = 200000;
    Vector3 *n = hemisphereSample(count, 0x1234567u);
    // Reference numbers (1e6 uniform hemisphere normals): RGB8 0.17 / 0.38, XY8 0.47 / 5.8, hemi-oct 0.24 / 0.55
    struct { int encoding; const char *name; double mean, max; } ref[3] = {
        { RBL_NORMAL_RGB, "rgb8", 0.17, 0.38 }, { RBL_NORMAL_XY, "xy8", 0.47, 5.8 }, { RBL_NORMAL_HEMIOCT, "hemioct8", 0.24, 0.55 } };
    for (int e = 0; e < 3; e++)
    {
        RblNormalErrorStats s = RblMeasureNormalEncoding(ref[e].encoding, n, count);
        printf("    %-8s mean %.4f  p99 %.4f  max %.4f degrees over %d normals\n", ref[e].name, s.mean, s.p99, s.max, s.count);
        RT_CHECK(s.count == count, "%s: count %d", ref[e].name, s.count);
        RT_CHECK(fabs(s.mean - ref[e].mean) <= 0.2*ref[e].mean, "%s: mean %.4f, reference %.2f +-20%%", ref[e].name, s.mean, ref[e].mean);
        RT_CHECK(fabs(s.max - ref[e].max) <= 0.2*ref[e].max, "%s: max %.4f, reference %.2f +-20%%", ref[e].name, s.max, ref[e].max);
        RT_CHECK((s.mean <= s.p99) && (s.p99 <= s.max), "%s: mean %.4f p99 %.4f max %.4f out of order", ref[e].name, s.mean, s.p99, s.max);
    }
    free(n);
}

static void test_materials_default_hemioct_meets_max_0_6_and_mean_0_25_degrees(void)
{
    const int count = 200000;
    Vector3 *n = hemisphereSample(count, 0xBADC0DEu);
    RblNormalErrorStats s = RblMeasureNormalEncoding(RBL_NORMAL_HEMIOCT, n, count);
    RT_CHECK(s.max <= 0.6, "hemi-oct max %.4f > 0.6 degrees", s.max);
    RT_CHECK(s.mean <= 0.25, "hemi-oct mean %.4f > 0.25 degrees", s.mean);
    free(n);

    // The packing default (normalEncoding 0) is this encoding
    Image albedo = GenImageColor(4, 4, WHITE), normal = GenImageColor(4, 4, (Color){ 128, 128, 255, 255 });
    RblMaterialSource src = sourceOf(albedo);
    src.normal = normal;
    RblPackedMaterial packed;
    RT_CHECK(RblPackMaterial(&src, &packed), "pack failed");
    RT_CHECK(packed.layout.normalEncoding == RBL_NORMAL_HEMIOCT, "default encoding %d", packed.layout.normalEncoding);
    RblUnloadPackedMaterial(&packed);
    UnloadImage(albedo); UnloadImage(normal);
}

static void test_materials_xy_error_is_small_near_the_pole_and_over_3_degrees_at_grazing_angles(void)
{
    const int count = 200000;
    Vector3 *n = hemisphereSample(count, 777u);
    double maxPole = 0.0, maxGrazing = 0.0;
    for (int i = 0; i < count; i++)
    {
        unsigned char code[3];
        RblEncodeNormal(n[i], RBL_NORMAL_XY, code);
        double e = angleDeg(n[i], RblDecodeNormal(code, RBL_NORMAL_XY));
        if ((n[i].z > 0.7f) && (e > maxPole)) maxPole = e;
        if ((n[i].z < 0.1f) && (e > maxGrazing)) maxGrazing = e;
    }
    printf("    xy8 max error: %.3f degrees for z > 0.7, %.3f degrees for z < 0.1\n", maxPole, maxGrazing);
    RT_CHECK(maxPole < 0.6, "xy near the pole: max %.3f", maxPole);
    RT_CHECK(maxGrazing > 3.0, "xy at grazing angles: max %.3f, expected > 3 degrees", maxGrazing);
    free(n);
}

static void test_materials_precise_hemioct_is_never_worse_than_rounding_and_better_on_average(void)
{
    const int count = 200000;
    Vector3 *n = hemisphereSample(count, 4242u);
    double sumPrecise = 0.0, sumRounded = 0.0, worstLoss = 0.0;
    int better = 0, notNeighbour = 0;
    for (int i = 0; i < count; i++)
    {
        unsigned char precise[3], rounded[3];
        RblEncodeNormal(n[i], RBL_NORMAL_HEMIOCT, precise);
        hemiOctRounded(n[i], rounded);
        double ep = angleDeg(n[i], RblDecodeNormal(precise, RBL_NORMAL_HEMIOCT));
        double er = angleDeg(n[i], RblDecodeNormal(rounded, RBL_NORMAL_HEMIOCT));
        sumPrecise += ep; sumRounded += er;
        if (ep - er > worstLoss) worstLoss = ep - er;
        if (ep < er) better++;
        if ((abs(precise[0] - rounded[0]) > 1) || (abs(precise[1] - rounded[1]) > 1)) notNeighbour++;
    }
    printf("    hemi-oct mean error: precise %.4f, rounded %.4f degrees; precise better for %d of %d\n",
           sumPrecise/count, sumRounded/count, better, count);
    RT_CHECK(worstLoss <= 1e-9, "precise worse than rounding by %.3g degrees", worstLoss);
    RT_CHECK(sumPrecise < sumRounded, "precise mean %.4f not below rounded %.4f", sumPrecise/count, sumRounded/count);
    RT_CHECK(better > count/100, "precise better for only %d normals", better);
    RT_CHECK(notNeighbour == 0, "%d codes are not floor/ceil neighbours of the rounded code", notNeighbour);
    free(n);
}

static void test_materials_every_code_decodes_to_a_finite_unit_normal(void)
{
    int bad[4] = { 0, 0, 0, 0 };
    for (int r = 0; r < 256; r++)
        for (int g = 0; g < 256; g++)
            for (int b = 0; b < 256; b++)
            {
                unsigned char c[3] = { (unsigned char)r, (unsigned char)g, (unsigned char)b };
                for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++)
                {
                    if ((e != RBL_NORMAL_RGB) && (b != (r ^ g))) continue;     // two-channel codes: every (r,g) once
                    Vector3 n = RblDecodeNormal(c, e);
                    bool ok = rtFinite(n.x) && rtFinite(n.y) && rtFinite(n.z) && (fabs(lenOf(n) - 1.0) <= 1e-6);
                    if ((e != RBL_NORMAL_RGB) && (n.z < 0.0f)) ok = false;
                    if (!ok && (bad[e]++ == 0)) RT_CHECK(false, "encoding %d: code %d,%d,%d decodes to %g %g %g", e, r, g, b, n.x, n.y, n.z);
                }
            }
    for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++) RT_CHECK(bad[e] == 0, "encoding %d: %d bad codes", e, bad[e]);

    // The "no normal" greys are the flat normal, exactly
    const unsigned char greys[4][3] = { { 128, 128, 128 }, { 127, 127, 127 }, { 127, 128, 128 }, { 128, 128, 129 } };
    for (int i = 0; i < 4; i++)
    {
        Vector3 n = RblDecodeNormal(greys[i], RBL_NORMAL_RGB);
        RT_CHECK((n.x == 0.0f) && (n.y == 0.0f) && (n.z == 1.0f), "rgb %d,%d,%d decodes to %g %g %g, expected flat",
                 greys[i][0], greys[i][1], greys[i][2], n.x, n.y, n.z);
    }
    Vector3 none = RblDecodeNormal(greys[0], RBL_NORMAL_NONE);
    RT_CHECK((none.x == 0.0f) && (none.y == 0.0f) && (none.z == 1.0f), "NONE decodes to %g %g %g", none.x, none.y, none.z);
}

static void test_materials_encoder_refuses_nan_inf_zero_and_maps_below_hemisphere_input_to_defined_codes(void)
{
    const float nan = NAN, inf = INFINITY;
    SetTraceLogCallback(matCountingLog);
    for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++)
    {
        unsigned char flat[3], c[3];
        RblEncodeNormal((Vector3){ 0.0f, 0.0f, 1.0f }, e, flat);
        // No direction at all: refused with one log line, the output untouched
        const Vector3 refused[3] = { { nan, 0.0f, 1.0f }, { 0.0f, 0.0f, 0.0f }, { inf, 1.0f, 1.0f } };
        for (int i = 0; i < 3; i++)
        {
            memset(c, 0xA5, 3);
            matWarnings = 0;
            RblEncodeNormal(refused[i], e, c);
            RT_CHECK(c[0] == 0xA5 && c[1] == 0xA5 && c[2] == 0xA5 && matWarnings == 1, "encoding %d input %d: out written or %d warnings", e, i, matWarnings);
        }
        // Straight down (clamped onto the hemisphere's pole) and a long +Z: the flat code
        const Vector3 toFlat[2] = { { 0.0f, 0.0f, -1.0f }, { 0.0f, 0.0f, 7.0f } };
        for (int i = 0; i < 2; i++)
        {
            RblEncodeNormal(toFlat[i], e, c);
            RT_CHECK(memcmp(c, flat, 3) == 0, "encoding %d input %d: code %d,%d,%d, flat is %d,%d,%d", e, i, c[0], c[1], c[2], flat[0], flat[1], flat[2]);
        }
        // Below the hemisphere: z clamps to 0 (then normalised)
        RblEncodeNormal((Vector3){ 0.6f, 0.0f, -0.8f }, e, c);
        double err = angleDeg(RblDecodeNormal(c, e), (Vector3){ 1.0f, 0.0f, 0.0f });
        RT_CHECK(err < ((e == RBL_NORMAL_XY)? 6.0 : 0.6), "encoding %d: (0.6,0,-0.8) decodes %.3f degrees from (1,0,0)", e, err);
        // Length does not matter
        unsigned char a[3], b[3];
        RblEncodeNormal((Vector3){ 0.3f, -0.4f, 0.5f }, e, a);
        RblEncodeNormal((Vector3){ 3.0f, -4.0f, 5.0f }, e, b);
        RT_CHECK(memcmp(a, b, 3) == 0, "encoding %d: scaled inputs encode differently", e);
    }
    matWarnings = 0;
    Vector3 n = RblDecodeNormal(NULL, RBL_NORMAL_RGB);
    RT_CHECK(n.z == 1.0f && matWarnings == 1, "NULL decodes to %g %g %g (%d warnings)", n.x, n.y, n.z, matWarnings);
    SetTraceLogCallback(NULL);
}

static int compareDouble(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y)? -1 : (x > y)? 1 : 0;
}

static void test_materials_measure_reports_mean_nearest_rank_p99_max_and_counts_only_valid_normals(void)
{
    const int count = 1003;
    Vector3 *n = hemisphereSample(count, 31337u);
    n[10] = (Vector3){ NAN, 0.0f, 1.0f };           // not counted: no direction to compare with
    n[20] = (Vector3){ 0.0f, 0.0f, 0.0f };
    n[30] = (Vector3){ 1.0f, INFINITY, 0.0f };
    for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++)
    {
        double errors[1003], sum = 0.0;
        int m = 0;
        for (int i = 0; i < count; i++)
        {
            if ((i == 10) || (i == 20) || (i == 30)) continue;
            unsigned char c[3];
            RblEncodeNormal(n[i], e, c);
            errors[m] = angleDeg(n[i], RblDecodeNormal(c, e));
            sum += errors[m++];
        }
        qsort(errors, (size_t)m, sizeof(double), compareDouble);
        int rank = (int)ceil(0.99*m);                // nearest rank: 990 of 1000
        RblNormalErrorStats s = RblMeasureNormalEncoding(e, n, count);
        RT_CHECK(s.count == 1000, "encoding %d: count %d, expected 1000", e, s.count);
        RT_CHECK(fabs(s.mean - sum/m) <= 1e-9, "encoding %d: mean %.9f vs %.9f", e, s.mean, sum/m);
        RT_CHECK(s.p99 == errors[rank - 1], "encoding %d: p99 %.9f vs %.9f", e, s.p99, errors[rank - 1]);
        RT_CHECK(s.max == errors[m - 1], "encoding %d: max %.9f vs %.9f", e, s.max, errors[m - 1]);
    }
    SetTraceLogCallback(matCountingLog);
    matWarnings = 0;
    RblNormalErrorStats s = RblMeasureNormalEncoding(RBL_NORMAL_NONE, n, count);
    SetTraceLogCallback(NULL);
    RT_CHECK((s.count == 0) && (matWarnings == 1), "NONE: count %d, %d warnings", s.count, matWarnings);
    s = RblMeasureNormalEncoding(RBL_NORMAL_RGB, NULL, 5);
    RT_CHECK(s.count == 0, "NULL normals: count %d", s.count);
    free(n);
}

// ---- generators ---------------------------------------------------------------------------------
// Float height image (R32: heights used as stored, not clamped) from a function of the texel
static Image heightImage(int w, int h, double (*f)(int x, int y, const double *p), const double *p)
{
    Image img = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R32);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) ((float *)img.data)[y*w + x] = (float)f(x, y, p);
    return img;
}

static double rampRight(int x, int y, const double *p) { (void)y; return x*p[0]; }
static double rampUp(int x, int y, const double *p) { (void)x; return (p[1] - 1 - y)*p[0]; }    // rises toward row 0
static double sphereBump(int x, int y, const double *p)
{
    double dx = x - p[0], dy = y - p[1], r2 = p[2]*p[2] - dx*dx - dy*dy;
    return (r2 > 0.0)? sqrt(r2)/p[3] : 0.0;
}

static Vector3 decodedTexel(Image img, int x, int y)
{
    return RblDecodeNormal(texel4(img, x, y), RBL_NORMAL_RGB);
}

static void test_materials_height_plane_tilted_by_a_known_angle_gives_that_normal(void)
{
    const int size = 24;
    const double angles[4] = { 10.0, 30.0, 45.0, 60.0 };
    const float strengths[3] = { 1.0f, 2.5f, 0.25f };
    double worstExact = 0.0, worstDecoded = 0.0;
    for (int a = 0; a < 4; a++)
        for (int s = 0; s < 3; s++)
            for (int dir = 0; dir < 2; dir++)
            {
                double t = tan(angles[a]/MAT_DEG), sn = sin(angles[a]/MAT_DEG), cs = cos(angles[a]/MAT_DEG);
                double p[2] = { t/strengths[s], size };   // height units per texel = tan/strength
                Image height = heightImage(size, size, dir? rampUp : rampRight, p);
                // Rising to the right faces left (-X); rising toward the image top faces down the image (-Y)
                Vector3 expect = dir? (Vector3){ 0.0f, (float)-sn, (float)cs } : (Vector3){ (float)-sn, 0.0f, (float)cs };
                Image map = RblGenNormalMapFromHeight(height, strengths[s], false);
                RT_CHECK((map.format == PIXELFORMAT_UNCOMPRESSED_R8G8B8A8) && (map.width == size) && (map.mipmaps == 1), "output format");
                for (int y = 1; y < size - 1; y++)
                    for (int x = 1; x < size - 1; x++)
                    {
                        Vector3 n = rbl__heightNormal((const float *)height.data, size, size, x, y, strengths[s], false);
                        double d = fmax(fabs(n.x - expect.x), fmax(fabs(n.y - expect.y), fabs(n.z - expect.z)));
                        if (d > worstExact) worstExact = d;
                        double e = angleDeg(decodedTexel(map, x, y), expect);
                        if (e > worstDecoded) worstDecoded = e;
                        RT_CHECK(texel4(map, x, y)[3] == 255, "alpha");
                    }
                UnloadImage(height); UnloadImage(map);
            }
    printf("    tilted planes: worst component error %.2e before quantisation, %.3f degrees after RGB8 decode\n", worstExact, worstDecoded);
    RT_CHECK(worstExact <= 1e-5, "unquantised normal off by %.3g", worstExact);
    RT_CHECK(worstDecoded <= 0.4, "decoded normal off by %.3f degrees (RGB8 max error 0.38)", worstDecoded);
}

static void test_materials_strength_is_height_units_per_texel_so_one_per_texel_at_strength_1_is_45_degrees(void)
{
    const double cases[3][2] = { { 1.0, 1.0 }, { 0.5, 2.0 }, { 2.0, 0.5 } };     // height step per texel, strength
    for (int c = 0; c < 3; c++)
    {
        double p[1] = { cases[c][0] };
        Image height = heightImage(8, 8, rampRight, p);
        Vector3 n = rbl__heightNormal((const float *)height.data, 8, 8, 4, 4, (float)cases[c][1], false);
        double slope = atan2(-n.x, n.z)*MAT_DEG;
        RT_CHECK(fabs(slope - 45.0) <= 1e-4, "step %.1f strength %.1f: slope %.5f degrees, expected 45", cases[c][0], cases[c][1], slope);
        UnloadImage(height);
    }
    // strength 2 doubles the slope's tangent
    double p[1] = { 0.25 };
    Image height = heightImage(8, 8, rampRight, p);
    Vector3 n1 = rbl__heightNormal((const float *)height.data, 8, 8, 4, 4, 1.0f, false);
    Vector3 n2 = rbl__heightNormal((const float *)height.data, 8, 8, 4, 4, 2.0f, false);
    RT_CHECK(fabs((-n2.x/n2.z) - 2.0*(-n1.x/n1.z)) <= 1e-6, "tangent %.6f vs 2 x %.6f", -n2.x/n2.z, -n1.x/n1.z);
    UnloadImage(height);
}

static void test_materials_height_rising_toward_the_image_top_tilts_normals_to_minus_y(void)
{
    // 8-bit grey: brighter toward row 0 (the top of the image as seen)
    Image height = matImage(16, 16, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) ((unsigned char *)height.data)[y*16 + x] = (unsigned char)(255 - y*16);
    Image map = RblGenNormalMapFromHeight(height, 4.0f, false);
    for (int y = 1; y < 15; y++)
    {
        Vector3 n = decodedTexel(map, 8, y);
        RT_CHECK(n.y < -0.1f, "row %d: n.y = %.3f, a surface rising toward the top faces down the image (-Y)", y, n.y);
        RT_CHECK(fabsf(n.x) < 0.01f, "row %d: n.x = %.3f", y, n.x);
    }
    UnloadImage(map);
    // and the same rising to the right faces left (-X)
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) ((unsigned char *)height.data)[y*16 + x] = (unsigned char)(x*16);
    map = RblGenNormalMapFromHeight(height, 4.0f, false);
    Vector3 n = decodedTexel(map, 8, 8);
    RT_CHECK((n.x < -0.1f) && (fabsf(n.y) < 0.01f), "rising right: %.3f %.3f", n.x, n.y);
    UnloadImage(map);
    UnloadImage(height);
}

static void test_materials_hemisphere_bump_gives_the_analytic_sphere_normals(void)
{
    const int size = 128;
    const double cx = 64.0, cy = 64.0, radius = 50.0, strength = 4.0;
    double p[4] = { cx, cy, radius, strength };
    Image height = heightImage(size, size, sphereBump, p);
    Image map = RblGenNormalMapFromHeight(height, (float)strength, false);
    double worst = 0.0;
    int checked = 0;
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++)
        {
            double dx = x - cx, dup = cy - y;            // +Y is image up
            if (dx*dx + dup*dup > (0.8*radius)*(0.8*radius)) continue;     // away from the rim
            double z = sqrt(radius*radius - dx*dx - dup*dup);
            double e = angleDeg(decodedTexel(map, x, y), (Vector3){ (float)dx, (float)dup, (float)z });
            if (e > worst) worst = e;
            checked++;
        }
    printf("    sphere bump: worst %.3f degrees over %d interior texels\n", worst, checked);
    RT_CHECK(worst <= 0.5, "sphere normals off by %.3f degrees", worst);
    UnloadImage(height); UnloadImage(map);
}

static double periodic(int x, int y, const double *p) { return p[0]*sin(2.0*MAT_PI*x/p[1]) + p[0]*cos(2.0*MAT_PI*y/p[1]); }

static void test_materials_wrap_edges_continue_across_the_border_and_clamp_edges_repeat_the_edge_texel(void)
{
    const int size = 16;
    double p[2] = { 3.0, size };
    Image height = heightImage(size, size, periodic, p);
    // Wrap: translation invariant, so every texel equals the one-texel-shifted map's texel
    Image shifted = matImage(size, size, PIXELFORMAT_UNCOMPRESSED_R32);
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++) ((float *)shifted.data)[y*size + x] = ((float *)height.data)[((y + 3)%size)*size + (x + 5)%size];
    Image a = RblGenNormalMapFromHeight(height, 1.0f, true), b = RblGenNormalMapFromHeight(shifted, 1.0f, true);
    int differ = 0;
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++)
            if (memcmp(texel4(b, x, y), texel4(a, (x + 5)%size, (y + 3)%size), 4) != 0) differ++;
    RT_CHECK(differ == 0, "wrap: %d texels differ from the shifted map", differ);
    UnloadImage(a); UnloadImage(b); UnloadImage(shifted); UnloadImage(height);

    // Clamp: a ramp's edge column sees the edge texel repeated, so half the slope (one-sided / 2)
    double q[1] = { 1.0 };
    Image ramp = heightImage(size, size, rampRight, q);
    Vector3 edge = rbl__heightNormal((const float *)ramp.data, size, size, 0, 5, 1.0f, false);
    Vector3 inner = rbl__heightNormal((const float *)ramp.data, size, size, 1, 5, 1.0f, false);
    Vector3 wrapped = rbl__heightNormal((const float *)ramp.data, size, size, 0, 5, 1.0f, true);
    RT_CHECK(fabs(-edge.x/edge.z - 0.5) <= 1e-6, "clamped edge slope %.6f, expected 0.5", -edge.x/edge.z);
    RT_CHECK(fabs(-inner.x/inner.z - 1.0) <= 1e-6, "inner slope %.6f, expected 1", -inner.x/inner.z);
    RT_CHECK(fabs(-wrapped.x/wrapped.z - (1.0 - 15.0)/2.0) <= 1e-5, "wrapped edge slope %.6f, expected -7", -wrapped.x/wrapped.z);
    UnloadImage(ramp);
}

static void test_materials_height_from_luminance_is_rec709_of_the_linearised_colour(void)
{
    const Color colors[7] = { WHITE, BLACK, { 188, 188, 188, 255 }, { 0, 255, 0, 255 }, { 255, 0, 0, 255 }, { 0, 0, 255, 255 }, { 255, 255, 255, 0 } };
    const unsigned char expect[7] = { 255, 0, 128, 182, 54, 18, 255 };     // 0.2126 R + 0.7152 G + 0.0722 B, linear; alpha ignored
    Image albedo = matImage(7, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    for (int i = 0; i < 7; i++) memcpy(texel4(albedo, i, 0), &colors[i], 4);
    Image h = RblGenHeightFromLuminance(albedo);
    RT_CHECK((h.format == PIXELFORMAT_UNCOMPRESSED_GRAYSCALE) && (h.width == 7) && (h.height == 1), "format %d", h.format);
    for (int i = 0; (i < 7) && (h.data != NULL); i++)
        RT_CHECK(((unsigned char *)h.data)[i] == expect[i], "colour %d: height %d, expected %d", i, ((unsigned char *)h.data)[i], expect[i]);
    UnloadImage(h);
    // a float albedo gives the same heights
    Image f = ImageCopy(albedo);
    ImageFormat(&f, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32);
    h = RblGenHeightFromLuminance(f);
    for (int i = 0; (i < 7) && (h.data != NULL); i++)
        RT_CHECK(abs(((unsigned char *)h.data)[i] - expect[i]) <= 1, "float colour %d: height %d, expected %d", i, ((unsigned char *)h.data)[i], expect[i]);
    UnloadImage(h); UnloadImage(f); UnloadImage(albedo);
}

static void test_materials_occlusion_is_open_on_flat_ground_and_on_tops_and_darker_in_pits(void)
{
    const int size = 32;
    Image height = matImage(size, size, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    memset(height.data, 128, (size_t)size*size);
    for (int y = 14; y < 17; y++)
        for (int x = 14; x < 17; x++) ((unsigned char *)height.data)[y*size + x] = 0;        // a 3x3 pit
    for (int y = 4; y < 7; y++)
        for (int x = 4; x < 7; x++) ((unsigned char *)height.data)[y*size + x] = 255;      // a 3x3 bump
    Image ao = RblGenOcclusionFromHeight(height, 4, 1.0f);
    RT_CHECK(ao.format == PIXELFORMAT_UNCOMPRESSED_GRAYSCALE, "format %d", ao.format);
    const unsigned char *o = (const unsigned char *)ao.data;
    RT_CHECK(o[26*size + 26] == 255, "flat ground: %d, expected 255", o[26*size + 26]);
    RT_CHECK(o[5*size + 5] == 255, "top of the bump: %d, expected 255", o[5*size + 5]);
    // pit centre: mean of the 9x9 window = (72 x 128/255)/81, depth = that - 0 -> 1 - depth
    double expect = 1.0 - (72.0*128.0/255.0)/81.0;
    RT_CHECK(abs(o[15*size + 15] - (int)floor(expect*255.0 + 0.5)) <= 1, "pit centre %d, expected %.1f", o[15*size + 15], expect*255.0);
    RT_CHECK(o[15*size + 12] == 255, "ground at the pit's rim (above its local mean): %d, expected 255", o[15*size + 12]);
    RT_CHECK(o[15*size + 14] < 255, "pit edge texel: %d, expected darker than 255", o[15*size + 14]);
    Image stronger = RblGenOcclusionFromHeight(height, 4, 2.0f);
    RT_CHECK(((unsigned char *)stronger.data)[15*size + 15] < o[15*size + 15], "strength 2 is not darker");
    UnloadImage(stronger);
    UnloadImage(ao);

    SetTraceLogCallback(matCountingLog);
    matWarnings = 0;
    Image bad = RblGenOcclusionFromHeight(height, -1, 1.0f);
    Image bad2 = RblGenNormalMapFromHeight(height, NAN, false);
    Image empty;
    memset(&empty, 0, sizeof(empty));
    Image bad3 = RblGenHeightFromLuminance(empty);
    SetTraceLogCallback(NULL);
    RT_CHECK((bad.data == NULL) && (bad2.data == NULL) && (bad3.data == NULL) && (matWarnings == 3), "bad arguments: %d warnings", matWarnings);
    UnloadImage(height);
}

// ---- packing ------------------------------------------------------------------------------------
static void test_materials_pack_layout_flags_follow_the_present_maps_and_absent_channels_take_defaults(void)
{
    const int w = 8, h = 4;
    Image albedo = GenImageColor(w, h, (Color){ 10, 20, 30, 40 });
    Image normal = GenImageColor(w, h, (Color){ 200, 100, 220, 255 });
    Image spec = GenImageColor(w, h, (Color){ 77, 1, 2, 255 });         // red channel is the value
    Image occ = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    memset(occ.data, 99, (size_t)w*h);
    Image emisGrey = GenImageColor(w, h, (Color){ 60, 60, 60, 255 });
    unsigned char flatHemi[3], flatXY[3], flatRGB[3];
    RblEncodeNormal((Vector3){ 0, 0, 1 }, RBL_NORMAL_HEMIOCT, flatHemi);
    RblEncodeNormal((Vector3){ 0, 0, 1 }, RBL_NORMAL_XY, flatXY);
    RblEncodeNormal((Vector3){ 0, 0, 1 }, RBL_NORMAL_RGB, flatRGB);

    struct { bool n, s, o, e; int encoding; int expectEncoding; } cases[] = {
        { false, false, false, false, 0, RBL_NORMAL_NONE },
        { true, false, false, false, 0, RBL_NORMAL_HEMIOCT },
        { false, true, false, false, 0, RBL_NORMAL_NONE },
        { false, false, true, false, RBL_NORMAL_XY, RBL_NORMAL_NONE },
        { true, true, true, true, RBL_NORMAL_XY, RBL_NORMAL_XY },
        { true, false, true, false, RBL_NORMAL_RGB, RBL_NORMAL_RGB },
        { false, false, true, true, RBL_NORMAL_RGB, RBL_NORMAL_NONE },
    };
    for (int c = 0; c < (int)(sizeof(cases)/sizeof(cases[0])); c++)
    {
        RblMaterialSource src = sourceOf(albedo);
        if (cases[c].n) src.normal = normal;
        if (cases[c].s) src.specular = spec;
        if (cases[c].o) src.occlusion = occ;
        if (cases[c].e) src.emissive = emisGrey;
        src.normalEncoding = cases[c].encoding;
        RblPackedMaterial p;
        if (!RblPackMaterial(&src, &p)) { RT_CHECK(false, "case %d: pack failed", c); continue; }
        bool anyMaterial = cases[c].n || cases[c].s || cases[c].o;
        RT_CHECK(p.layout.normalEncoding == cases[c].expectEncoding, "case %d: encoding %d", c, p.layout.normalEncoding);
        RT_CHECK((p.layout.specular == cases[c].s) && (p.layout.occlusion == cases[c].o), "case %d: flags", c);
        RT_CHECK(p.layout.emissive == (cases[c].e? RBL_EMISSIVE_MASK : RBL_EMISSIVE_NONE), "case %d: emissive %d", c, p.layout.emissive);
        RT_CHECK((p.material.data != NULL) == anyMaterial, "case %d: material data %p", c, p.material.data);
        RT_CHECK((p.emissive.data != NULL) == cases[c].e, "case %d: emissive data", c);
        RT_CHECK((p.albedo.format == PIXELFORMAT_UNCOMPRESSED_R8G8B8A8) && (p.albedo.mipmaps == 1) && (p.albedo.width == w), "case %d: albedo", c);
        RT_CHECK(memcmp(texel4(p.albedo, 3, 2), &(Color){ 10, 20, 30, 40 }, 4) == 0, "case %d: albedo copied", c);
        if (anyMaterial && (p.material.data != NULL))
        {
            RT_CHECK((p.material.format == PIXELFORMAT_UNCOMPRESSED_R8G8B8A8) && (p.material.mipmaps == 1), "case %d: material format", c);
            int enc = (cases[c].encoding == 0)? RBL_NORMAL_HEMIOCT : cases[c].encoding;
            const unsigned char *m = texel4(p.material, 5, 1);
            unsigned char expect[3];
            if (cases[c].n) RblEncodeNormal((Vector3){ 200/255.0f*2 - 1, 100/255.0f*2 - 1, 220/255.0f*2 - 1 }, enc, expect);   // c*2 - 1, normalised by the encoder
            else memcpy(expect, (enc == RBL_NORMAL_HEMIOCT)? flatHemi : (enc == RBL_NORMAL_XY)? flatXY : flatRGB, 3);
            int nc = (enc == RBL_NORMAL_RGB)? 3 : 2;
            RT_CHECK(memcmp(m, expect, (size_t)nc) == 0, "case %d: normal channels %d,%d,%d expected %d,%d,%d", c, m[0], m[1], m[2], expect[0], expect[1], expect[2]);
            if (enc != RBL_NORMAL_RGB) RT_CHECK(m[2] == (cases[c].s? 77 : 128), "case %d: specular %d", c, m[2]);
            RT_CHECK(m[3] == (cases[c].o? 99 : 255), "case %d: occlusion %d", c, m[3]);
        }
        RblUnloadPackedMaterial(&p);
    }
    UnloadImage(albedo); UnloadImage(normal); UnloadImage(spec); UnloadImage(occ); UnloadImage(emisGrey);
}

static void test_materials_pack_directx_flag_flips_the_decoded_y(void)
{
    Image albedo = GenImageColor(4, 4, WHITE), normal = matImage(4, 4, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Vector3 tilt = { 0.3f, 0.5f, 0.81f };
    for (int i = 0; i < 16; i++) putNormal(normal, i%4, i/4, tilt);
    for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++)
    {
        RblMaterialSource src = sourceOf(albedo);
        src.normal = normal;
        src.normalEncoding = e;
        RblPackedMaterial gl, dx;
        RT_CHECK(RblPackMaterial(&src, &gl), "pack");
        src.normalDirectX = true;
        RT_CHECK(RblPackMaterial(&src, &dx), "pack dx");
        Vector3 a = RblDecodeNormal(texel4(gl.material, 1, 1), e), b = RblDecodeNormal(texel4(dx.material, 1, 1), e);
        Vector3 flipped = { tilt.x, -tilt.y, tilt.z };
        RT_CHECK(angleDeg(a, tilt) < 1.5, "encoding %d: OpenGL map decodes %.3f degrees off", e, angleDeg(a, tilt));
        RT_CHECK(angleDeg(b, flipped) < 1.5, "encoding %d: DirectX map decodes %.3f degrees from the flipped normal", e, angleDeg(b, flipped));
        RT_CHECK((a.y > 0.4f) && (b.y < -0.4f) && (fabsf(a.x - b.x) < 0.01f), "encoding %d: y %.3f vs %.3f", e, a.y, b.y);
        RblUnloadPackedMaterial(&gl); RblUnloadPackedMaterial(&dx);
    }
    UnloadImage(albedo); UnloadImage(normal);
}

static void test_materials_pack_zero_vector_normal_texels_become_flat_never_nan(void)
{
    Image albedo = GenImageColor(4, 1, WHITE);
    Image normal = matImage(4, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8);
    const unsigned char texels[4][3] = { { 128, 128, 128 }, { 127, 127, 127 }, { 127, 128, 128 }, { 128, 127, 129 } };
    memcpy(normal.data, texels, sizeof(texels));
    Image normalF = matImage(4, 1, PIXELFORMAT_UNCOMPRESSED_R32G32B32);   // exact zero vectors, and NaN
    float *f = (float *)normalF.data;
    for (int i = 0; i < 12; i++) f[i] = 0.5f;
    f[3] = NAN;
    for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++)
        for (int which = 0; which < 2; which++)
        {
            RblMaterialSource src = sourceOf(albedo);
            src.normal = which? normalF : normal;
            src.normalEncoding = e;
            RblPackedMaterial p;
            if (!RblPackMaterial(&src, &p)) { RT_CHECK(false, "pack"); continue; }
            unsigned char flat[3];
            RblEncodeNormal((Vector3){ 0, 0, 1 }, e, flat);
            for (int i = 0; i < 4; i++)
            {
                const unsigned char *m = texel4(p.material, i, 0);
                RT_CHECK(memcmp(m, flat, (e == RBL_NORMAL_RGB)? 3 : 2) == 0, "encoding %d %s texel %d: code %d,%d,%d is not the flat code",
                         e, which? "float" : "rgb8", i, m[0], m[1], m[2]);
            }
            RblUnloadPackedMaterial(&p);
        }
    UnloadImage(albedo); UnloadImage(normal); UnloadImage(normalF);
}

static void test_materials_pack_rejects_invalid_input_with_a_warning_and_leaves_packed_untouched(void)
{
    const int w = 8, h = 8;
    Image albedo = GenImageColor(w, h, WHITE), small = GenImageColor(4, 8, WHITE), normal = GenImageColor(w, h, (Color){ 128, 128, 255, 255 });
    Image dxt = matImage(w, h, PIXELFORMAT_COMPRESSED_DXT1_RGB), odd = albedo;
    odd.format = 0;
    Image nullData = albedo, empty = albedo;
    nullData.data = NULL;
    empty.width = 0;
    Rectangle outside = { 4, 4, 5, 2 }, negative = { 1, 1, -2, 3 }, nanFrame = { NAN, 0, 2, 2 }, good = { 0, 0, 4, 4 };

    enum { CASES = 15 };
    RblMaterialSource s[CASES];
    const char *what[CASES] = { "NULL albedo", "empty albedo", "normal of another size", "compressed albedo", "compressed emissive",
                                "unknown format", "bad encoding", "RGB encoding with specular", "frame outside", "negative frame",
                                "NaN frame", "frames NULL", "negative frameCount", "negative height", "occlusion of another size" };
    for (int i = 0; i < CASES; i++) s[i] = sourceOf(albedo);
    s[0].albedo = nullData;
    s[1].albedo = empty;
    s[2].normal = small;
    s[3].albedo = dxt;
    s[4].emissive = dxt;
    s[5].specular = odd;
    s[6].normal = normal; s[6].normalEncoding = 9;
    s[7].normal = normal; s[7].specular = albedo; s[7].normalEncoding = RBL_NORMAL_RGB;
    s[8].frames = &outside; s[8].frameCount = 1;
    s[9].frames = &negative; s[9].frameCount = 1;
    s[10].frames = &nanFrame; s[10].frameCount = 1;
    s[11].frameCount = 2;
    s[12].frames = &good; s[12].frameCount = -1;
    s[13].albedo.height = -8;
    s[14].occlusion = small;

    SetTraceLogCallback(matCountingLog);
    for (int i = 0; i < CASES; i++)
    {
        RblPackedMaterial packed, sentinel;
        memset(&packed, 0xA5, sizeof(packed));
        memcpy(&sentinel, &packed, sizeof(packed));
        matWarnings = 0;
        bool ok = RblPackMaterial(&s[i], &packed);
        RT_CHECK(!ok, "%s: accepted", what[i]);
        RT_CHECK(matWarnings == 1, "%s: %d warnings logged", what[i], matWarnings);
        RT_CHECK(memcmp(&packed, &sentinel, sizeof(packed)) == 0, "%s: packed was written", what[i]);
    }
    matWarnings = 0;
    RblPackedMaterial packed;
    RT_CHECK(!RblPackMaterial(NULL, &packed) && !RblPackMaterial(&s[2], NULL) && (matWarnings == 2), "NULL arguments: %d warnings", matWarnings);
    SetTraceLogCallback(NULL);
    printf("    e.g. \"%s\"\n", matLastWarning);
    UnloadImage(albedo); UnloadImage(small); UnloadImage(normal); UnloadImage(dxt);
}

static void test_materials_pack_converts_grayscale_rgb565_and_float_inputs_instead_of_rejecting(void)
{
    const int w = 4, h = 2;
    // albedo as GRAYSCALE: grey RGB, alpha 255
    Image grey = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    for (int i = 0; i < w*h; i++) ((unsigned char *)grey.data)[i] = (unsigned char)(i*30);
    RblMaterialSource src = sourceOf(grey);
    RblPackedMaterial p;
    RT_CHECK(RblPackMaterial(&src, &p), "grayscale albedo rejected");
    for (int i = 0; (i < w*h) && (p.albedo.data != NULL); i++)
    {
        const unsigned char *t = texel4(p.albedo, i%w, i/w);
        RT_CHECK((t[0] == i*30) && (t[1] == i*30) && (t[2] == i*30) && (t[3] == 255), "grey texel %d: %d %d %d %d", i, t[0], t[1], t[2], t[3]);
    }
    RblUnloadPackedMaterial(&p);

    // albedo RGB565 and R32G32B32A32, specular R32 (grey float), emissive GRAY_ALPHA (a mask)
    Image rgb565 = GenImageColor(w, h, (Color){ 255, 0, 255, 255 });
    ImageFormat(&rgb565, PIXELFORMAT_UNCOMPRESSED_R5G6B5);
    Image rgbaF = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32);
    for (int i = 0; i < w*h; i++) { float *t = (float *)rgbaF.data + i*4; t[0] = 0.25f; t[1] = 1.5f; t[2] = -1.0f; t[3] = 0.5f; }
    Image specF = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R32);
    for (int i = 0; i < w*h; i++) ((float *)specF.data)[i] = 0.75f;
    Image emisGA = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_GRAY_ALPHA);
    for (int i = 0; i < w*h; i++) { ((unsigned char *)emisGA.data)[i*2] = 33; ((unsigned char *)emisGA.data)[i*2 + 1] = 7; }
    src = sourceOf(rgb565);
    src.specular = specF;
    src.emissive = emisGA;
    RT_CHECK(RblPackMaterial(&src, &p), "RGB565 albedo / R32 specular / GRAY_ALPHA emissive rejected");
    if (p.albedo.data != NULL)
    {
        const unsigned char *t = texel4(p.albedo, 1, 1), *m = texel4(p.material, 1, 1);
        RT_CHECK((t[0] == 255) && (t[1] == 0) && (t[2] == 255) && (t[3] == 255), "RGB565 texel %d %d %d %d", t[0], t[1], t[2], t[3]);
        RT_CHECK(m[2] == 191, "R32 specular 0.75 -> %d, expected 191", m[2]);
        RT_CHECK((p.layout.emissive == RBL_EMISSIVE_MASK) && (((unsigned char *)p.emissive.data)[3] == 33), "GRAY_ALPHA emissive");
    }
    RblUnloadPackedMaterial(&p);
    src = sourceOf(rgbaF);
    RT_CHECK(RblPackMaterial(&src, &p), "float albedo rejected");
    if (p.albedo.data != NULL)
    {
        const unsigned char *t = texel4(p.albedo, 0, 0);
        RT_CHECK((t[0] == 64) && (t[1] == 255) && (t[2] == 0) && (t[3] == 128), "float texel %d %d %d %d (clamped, rounded)", t[0], t[1], t[2], t[3]);
    }
    RblUnloadPackedMaterial(&p);

    // a 16-bit float normal map packs like its 8-bit original
    Image albedo = GenImageColor(w, h, WHITE), n8 = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    unsigned int seed = 5u;
    for (int i = 0; i < w*h; i++) putNormal(n8, i%w, i/w, (Vector3){ rtRandomRange(&seed, -0.6f, 0.6f), rtRandomRange(&seed, -0.6f, 0.6f), 0.7f });
    Image n16 = ImageCopy(n8);
    ImageFormat(&n16, PIXELFORMAT_UNCOMPRESSED_R16G16B16);
    RT_CHECK(n16.format == PIXELFORMAT_UNCOMPRESSED_R16G16B16, "test setup: R16G16B16 conversion");
    RblPackedMaterial a, b;
    src = sourceOf(albedo);
    src.normal = n8;
    RT_CHECK(RblPackMaterial(&src, &a), "8-bit normal");
    src.normal = n16;
    RT_CHECK(RblPackMaterial(&src, &b), "half-float normal rejected");
    for (int i = 0; (i < w*h) && (a.material.data != NULL) && (b.material.data != NULL); i++)
    {
        Vector3 input = RblDecodeNormal(texel4(n8, i%w, i/w), RBL_NORMAL_RGB);
        double e8 = angleDeg(RblDecodeNormal(texel4(a.material, i%w, i/w), RBL_NORMAL_HEMIOCT), input);
        double e16 = angleDeg(RblDecodeNormal(texel4(b.material, i%w, i/w), RBL_NORMAL_HEMIOCT), input);
        RT_CHECK((e8 < 0.6) && (e16 < 0.6), "texel %d: 8-bit map packs %.3f, half-float %.3f degrees from the input", i, e8, e16);
    }
    RblUnloadPackedMaterial(&a); RblUnloadPackedMaterial(&b);
    UnloadImage(grey); UnloadImage(rgb565); UnloadImage(rgbaF); UnloadImage(specF); UnloadImage(emisGA);
    UnloadImage(albedo); UnloadImage(n8); UnloadImage(n16);
}

static void test_materials_pack_grey_emissive_becomes_a_mask_and_coloured_emissive_stays_rgb(void)
{
    const int w = 6, h = 5;
    Image albedo = GenImageColor(w, h, WHITE), emissive = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    for (int i = 0; i < w*h; i++) { unsigned char *t = texel4(emissive, i%w, i/w); t[0] = t[1] = t[2] = (unsigned char)(i*8); t[3] = 255; }
    RblMaterialSource src = sourceOf(albedo);
    src.emissive = emissive;
    RblPackedMaterial p;
    RT_CHECK(RblPackMaterial(&src, &p), "pack");
    RT_CHECK((p.layout.emissive == RBL_EMISSIVE_MASK) && (p.emissive.format == PIXELFORMAT_UNCOMPRESSED_GRAYSCALE), "grey -> mask (%d)", p.layout.emissive);
    for (int i = 0; (i < w*h) && (p.emissive.data != NULL); i++)
        RT_CHECK(((unsigned char *)p.emissive.data)[i] == i*8, "mask %d = %d", i, ((unsigned char *)p.emissive.data)[i]);
    RblUnloadPackedMaterial(&p);
    texel4(emissive, 4, 3)[2] = 1;                 // one coloured texel (its grey is 8*22 = 176)
    RT_CHECK(RblPackMaterial(&src, &p), "pack");
    RT_CHECK((p.layout.emissive == RBL_EMISSIVE_RGB) && (p.emissive.format == PIXELFORMAT_UNCOMPRESSED_R8G8B8A8), "coloured -> rgb (%d)", p.layout.emissive);
    RT_CHECK((p.emissive.data != NULL) && (memcmp(p.emissive.data, emissive.data, (size_t)w*h*4) == 0), "rgb emissive copied");
    RblUnloadPackedMaterial(&p);
    UnloadImage(albedo); UnloadImage(emissive);
}

// Conservative frame footprint at a level: texels the frame touches (the header's documented rule)
static bool insideAnyFrame(const Rectangle *frames, int count, int w0, int h0, int w, int h, int x, int y)
{
    for (int f = 0; f < count; f++)
    {
        double sx = (double)w/w0, sy = (double)h/h0;
        int x0 = (int)floor(frames[f].x*sx), x1 = (int)ceil((frames[f].x + frames[f].width)*sx);
        int y0 = (int)floor(frames[f].y*sy), y1 = (int)ceil((frames[f].y + frames[f].height)*sy);
        if ((x >= x0) && (x < x1) && (y >= y0) && (y < y1)) return true;
    }
    return false;
}

// Every gutter texel of a level equals some frame texel at the smallest Chebyshev distance
static int gutterMismatches(const unsigned char *level, int bpp, const Rectangle *frames, int count, int w0, int h0, int w, int h)
{
    int bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
        {
            if (insideAnyFrame(frames, count, w0, h0, w, h, x, y)) continue;
            int best = 1 << 30;
            bool match = false;
            for (int v = 0; v < h; v++)
                for (int u = 0; u < w; u++)
                {
                    if (!insideAnyFrame(frames, count, w0, h0, w, h, u, v)) continue;
                    int d = (abs(u - x) > abs(v - y))? abs(u - x) : abs(v - y);
                    bool same = memcmp(level + ((size_t)y*w + x)*bpp, level + ((size_t)v*w + u)*bpp, (size_t)bpp) == 0;
                    if (d < best) { best = d; match = same; }
                    else if ((d == best) && same) match = true;
                }
            if (!match) bad++;
        }
    return bad;
}

static void test_materials_dilation_fills_gutters_with_the_nearest_frame_edge_and_mips_never_mix_frames(void)
{
    // 64x32 atlas: frame A at x 2..29, frame B at x 32..59 (a 2-texel gutter between), y 2..29
    const int w = 64, h = 32;
    const Rectangle frames[2] = { { 2, 2, 28, 28 }, { 32, 2, 28, 28 } };
    Image albedo = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8), normal = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Image spec = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE), emissive = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_GRAYSCALE);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
        {
            int f = insideAnyFrame(&frames[0], 1, w, h, w, h, x, y)? 0 : insideAnyFrame(&frames[1], 1, w, h, w, h, x, y)? 1 : -1;
            unsigned char *a = texel4(albedo, x, y);
            // A: shades of red, B: shades of blue, gutter: transparent green garbage
            a[0] = (f == 0)? (unsigned char)(128 + x*3 + y) : 0;
            a[1] = (f < 0)? 255 : 0;
            a[2] = (f == 1)? (unsigned char)(100 + (x - 32)*4 + y) : 0;
            a[3] = (f < 0)? 0 : 255;
            putNormal(normal, x, y, (f == 0)? (Vector3){ 0.5f, 0.1f, 0.86f } : (f == 1)? (Vector3){ -0.5f, 0.2f, 0.84f } : (Vector3){ 0.0f, -0.9f, 0.43f });
            ((unsigned char *)spec.data)[y*w + x] = (f == 0)? 50 : (f == 1)? 200 : 7;
            ((unsigned char *)emissive.data)[y*w + x] = (f == 0)? 100 : (f == 1)? 250 : 3;
        }
    RblMaterialSource src = sourceOf(albedo);
    src.normal = normal;
    src.specular = spec;
    src.emissive = emissive;
    src.frames = frames;
    src.frameCount = 2;
    src.mipmaps = true;
    RblPackedMaterial p;
    if (!RblPackMaterial(&src, &p)) { RT_CHECK(false, "pack"); return; }
    RT_CHECK((p.albedo.mipmaps == 7) && (p.material.mipmaps == 7) && (p.emissive.mipmaps == 7), "mip levels %d %d %d", p.albedo.mipmaps, p.material.mipmaps, p.emissive.mipmaps);

    // Level 0: texels inside frames unchanged
    int changed = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (insideAnyFrame(frames, 2, w, h, w, h, x, y) && (memcmp(texel4(p.albedo, x, y), texel4(albedo, x, y), 4) != 0)) changed++;
    RT_CHECK(changed == 0, "%d frame texels changed", changed);

    for (int level = 0; level < p.albedo.mipmaps; level++)
    {
        int lw, lh;
        const unsigned char *al = (const unsigned char *)p.albedo.data + mipOffset(w, h, 4, level, &lw, &lh);
        const unsigned char *ma = (const unsigned char *)p.material.data + mipOffset(w, h, 4, level, &lw, &lh);
        const unsigned char *em = (const unsigned char *)p.emissive.data + mipOffset(w, h, 1, level, &lw, &lh);
        // Gutters hold the nearest frame texel in every map
        int bad = gutterMismatches(al, 4, frames, 2, w, h, lw, lh) + gutterMismatches(ma, 4, frames, 2, w, h, lw, lh) +
                  gutterMismatches(em, 1, frames, 2, w, h, lw, lh);
        RT_CHECK(bad == 0, "level %d (%dx%d): %d gutter texels are not the nearest frame texel", level, lw, lh, bad);
        // No garbage anywhere; no B in texels whose footprint lies inside A
        int garbage = 0, bleed = 0;
        int scale = w/lw;
        for (int y = 0; y < lh; y++)
            for (int x = 0; x < lw; x++)
            {
                const unsigned char *t = al + ((size_t)y*lw + x)*4, *m = ma + ((size_t)y*lw + x)*4;
                if ((t[1] != 0) || (t[3] != 255) || (m[2] == 7) || (em[y*lw + x] < 100)) garbage++;
                bool insideA = (x*scale >= 2) && ((x + 1)*scale <= 30) && (y*scale >= 2) && ((y + 1)*scale <= 30);
                if (!insideA) continue;
                Vector3 n = RblDecodeNormal(m, RBL_NORMAL_HEMIOCT);
                if ((t[2] != 0) || (m[2] != 50) || (em[y*lw + x] != 100) || (angleDeg(n, (Vector3){ 0.5f, 0.1f, 0.86f }) > 1.5)) bleed++;
            }
        RT_CHECK(garbage == 0, "level %d: %d texels carry gutter garbage", level, garbage);
        RT_CHECK(bleed == 0, "level %d: %d texels inside frame A carry frame B's values", level, bleed);
    }
    RblUnloadPackedMaterial(&p);
    UnloadImage(albedo); UnloadImage(normal); UnloadImage(spec); UnloadImage(emissive);
}

static void test_materials_mip_normals_are_renormalised_and_opposite_tilts_average_to_flat(void)
{
    const int w = 16, h = 16;
    Image albedo = GenImageColor(w, h, WHITE);
    Image random = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8), checker = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Image opposite = matImage(w, h, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Vector3 *n = hemisphereSample(w*h, 99u);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
        {
            putNormal(random, x, y, n[y*w + x]);
            putNormal(checker, x, y, ((x + y)%2)? (Vector3){ 0.6f, 0.0f, 0.8f } : (Vector3){ -0.6f, 0.0f, 0.8f });
            putNormal(opposite, x, y, ((x + y)%2)? (Vector3){ 0.0f, 1.0f, 0.0f } : (Vector3){ 0.0f, -1.0f, 0.0f });
        }
    free(n);
    const double tolerance[4] = { 0.0, 0.6, 6.0, 0.4 };        // encoding max error (XY: grazing)
    for (int e = RBL_NORMAL_HEMIOCT; e <= RBL_NORMAL_RGB; e++)
    {
        RblMaterialSource src = sourceOf(albedo);
        src.normalEncoding = e;
        src.mipmaps = true;
        RblPackedMaterial pr, pc, po;
        src.normal = random;
        bool ok = RblPackMaterial(&src, &pr);
        src.normal = checker;
        ok = RblPackMaterial(&src, &pc) && ok;
        src.normal = opposite;
        ok = RblPackMaterial(&src, &po) && ok;
        if (!ok) { RT_CHECK(false, "pack"); continue; }
        RT_CHECK(pr.material.mipmaps == 5, "levels %d", pr.material.mipmaps);
        double worst = 0.0, worstFlat = 0.0, worstLen = 0.0;
        for (int level = 1; level < pr.material.mipmaps; level++)
        {
            int lw, lh, pw, ph;
            const unsigned char *cur = (const unsigned char *)pr.material.data + mipOffset(w, h, 4, level, &lw, &lh);
            const unsigned char *above = (const unsigned char *)pr.material.data + mipOffset(w, h, 4, level - 1, &pw, &ph);
            for (int y = 0; y < lh; y++)
                for (int x = 0; x < lw; x++)
                {
                    // the renormalised mean of the four texels above, within the encoding's error
                    double sum[3] = { 0, 0, 0 };
                    for (int k = 0; k < 4; k++)
                    {
                        Vector3 d = RblDecodeNormal(above + ((size_t)(2*y + k/2)*pw + 2*x + k%2)*4, e);
                        sum[0] += d.x; sum[1] += d.y; sum[2] += d.z;
                    }
                    Vector3 mean = { (float)sum[0], (float)sum[1], (float)sum[2] };
                    Vector3 got = RblDecodeNormal(cur + ((size_t)y*lw + x)*4, e);
                    if (lenOf(mean) > 1e-3) worst = fmax(worst, angleDeg(got, mean));
                    RT_CHECK(rtFinite(got.x) && rtFinite(got.y) && rtFinite(got.z) && (fabs(lenOf(got) - 1.0) < 1e-5), "level %d: not unit", level);
                    // stored vectors are unit too (RGB can store a shortened vector: it must not)
                    if (e == RBL_NORMAL_RGB)
                    {
                        const unsigned char *c = cur + ((size_t)y*lw + x)*4;
                        Vector3 raw = { c[0]/255.0f*2 - 1, c[1]/255.0f*2 - 1, c[2]/255.0f*2 - 1 };
                        worstLen = fmax(worstLen, fabs(lenOf(raw) - 1.0));
                    }
                }
            for (int which = 0; which < 2; which++)
            {
                const unsigned char *lev = (const unsigned char *)(which? po : pc).material.data + mipOffset(w, h, 4, level, &lw, &lh);
                for (int i = 0; i < lw*lh; i++) worstFlat = fmax(worstFlat, angleDeg(RblDecodeNormal(lev + (size_t)i*4, e), (Vector3){ 0, 0, 1 }));
            }
        }
        printf("    encoding %d: mip normal vs renormalised mean of the level above %.3f deg, checkerboards vs flat %.3f deg%s\n",
               e, worst, worstFlat, (e == RBL_NORMAL_RGB)? "" : "");
        RT_CHECK(worst <= tolerance[e], "encoding %d: mip normal %.3f degrees from the renormalised mean", e, worst);
        RT_CHECK(worstFlat <= 0.6, "encoding %d: opposite tilts average %.3f degrees from flat", e, worstFlat);
        if (e == RBL_NORMAL_RGB) RT_CHECK(worstLen <= 0.01, "RGB mip vectors stored %.3f from unit length (shortened, not renormalised)", worstLen);
        RblUnloadPackedMaterial(&pr); RblUnloadPackedMaterial(&pc); RblUnloadPackedMaterial(&po);
    }
    UnloadImage(albedo); UnloadImage(random); UnloadImage(checker); UnloadImage(opposite);
}

static void test_materials_albedo_mips_average_in_linear_light_weighted_by_alpha(void)
{
    Image albedo = matImage(2, 2, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    const unsigned char bw[16] = { 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255 };
    memcpy(albedo.data, bw, 16);
    RblMaterialSource src = sourceOf(albedo);
    src.mipmaps = true;
    src.emissive = albedo;                          // grey: a mask, averaged linearly (0,255,255,0 -> 128)
    RblPackedMaterial p;
    if (!RblPackMaterial(&src, &p)) { RT_CHECK(false, "pack"); return; }
    const unsigned char *m = (const unsigned char *)p.albedo.data + 16;
    RT_CHECK((p.albedo.mipmaps == 2) && (m[0] == 188) && (m[1] == 188) && (m[2] == 188) && (m[3] == 255),
             "black/white 2x2 -> %d %d %d %d, expected 188 (linear 0.5), not 128", m[0], m[1], m[2], m[3]);
    RT_CHECK(((unsigned char *)p.emissive.data)[4] == 128, "mask average %d, expected 128", ((unsigned char *)p.emissive.data)[4]);
    RblUnloadPackedMaterial(&p);

    // Transparent texels do not darken a cut-out's colour; alpha itself is a plain average
    const unsigned char cut[16] = { 255, 0, 0, 255, 0, 0, 0, 0, 0, 0, 0, 0, 255, 0, 0, 255 };
    memcpy(albedo.data, cut, 16);
    src.emissive.data = NULL;
    if (!RblPackMaterial(&src, &p)) { RT_CHECK(false, "pack"); return; }
    m = (const unsigned char *)p.albedo.data + 16;
    RT_CHECK((m[0] == 255) && (m[1] == 0) && (m[2] == 0) && (m[3] == 128), "red/transparent -> %d %d %d %d, expected 255 0 0 128", m[0], m[1], m[2], m[3]);
    RblUnloadPackedMaterial(&p);
    UnloadImage(albedo);
}

static void test_materials_mip_chain_uses_raylib_sizes_and_layout_and_odd_sizes_keep_constants(void)
{
    const int w = 12, h = 5;
    Image albedo = GenImageColor(w, h, (Color){ 90, 140, 200, 77 });
    Image emissive = GenImageColor(w, h, (Color){ 31, 31, 31, 255 });
    Image spec = GenImageColor(w, h, (Color){ 123, 0, 0, 255 });
    RblMaterialSource src = sourceOf(albedo);
    src.emissive = emissive;
    src.specular = spec;
    src.mipmaps = true;
    RblPackedMaterial p;
    if (!RblPackMaterial(&src, &p)) { RT_CHECK(false, "pack"); return; }
    Image reference = ImageCopy(albedo);
    ImageMipmaps(&reference);                       // raylib's own chain: level count and sizes
    RT_CHECK(p.albedo.mipmaps == reference.mipmaps, "levels %d, raylib %d", p.albedo.mipmaps, reference.mipmaps);
    RT_CHECK((p.material.mipmaps == reference.mipmaps) && (p.emissive.mipmaps == reference.mipmaps), "material/emissive levels");
    // ImageCopy sizes the data from the mip rule: a copy reads exactly the whole chain (ASan checks)
    Image copy = ImageCopy(p.albedo), copyMask = ImageCopy(p.emissive);
    RT_CHECK((copy.data != NULL) && (copyMask.data != NULL), "ImageCopy of the chains");
    UnloadImage(copy); UnloadImage(copyMask); UnloadImage(reference);
    // A constant image stays constant on every level, odd sides included (weights sum to 1)
    int off = 0;
    for (int level = 0; level < p.albedo.mipmaps; level++)
    {
        int lw, lh;
        size_t o4 = mipOffset(w, h, 4, level, &lw, &lh), o1 = mipOffset(w, h, 1, level, &lw, &lh);
        for (int i = 0; i < lw*lh; i++)
        {
            const unsigned char *a = (const unsigned char *)p.albedo.data + o4 + (size_t)i*4;
            const unsigned char *m = (const unsigned char *)p.material.data + o4 + (size_t)i*4;
            if ((a[0] != 90) || (a[1] != 140) || (a[2] != 200) || (a[3] != 77) || (m[2] != 123) || (m[3] != 255) ||
                (((const unsigned char *)p.emissive.data)[o1 + i] != 31)) off++;
        }
    }
    RT_CHECK(off == 0, "%d texels of a constant 12x5 chain changed", off);
    RblUnloadPackedMaterial(&p);
    UnloadImage(albedo); UnloadImage(emissive); UnloadImage(spec);
}

static void test_materials_unload_frees_and_zeroes_the_packed_material(void)
{
    Image albedo = GenImageColor(4, 4, WHITE), grey = GenImageColor(4, 4, GRAY);
    RblMaterialSource src = sourceOf(albedo);
    src.occlusion = grey;
    src.emissive = grey;
    src.mipmaps = true;
    RblPackedMaterial p, zero;
    memset(&zero, 0, sizeof(zero));
    RT_CHECK(RblPackMaterial(&src, &p), "pack");
    RblUnloadPackedMaterial(&p);
    RT_CHECK(memcmp(&p, &zero, sizeof(p)) == 0, "not zeroed");
    RblUnloadPackedMaterial(&p);                    // twice: nothing left to free
    RblUnloadPackedMaterial(NULL);
    UnloadImage(albedo); UnloadImage(grey);
}

// ---- alpha coverage across mips (RblMaterialSource.alphaCoverage) -------------------------------
// Share of a level's texels whose alpha passes an 8-bit threshold
static double covShare(const unsigned char *rgba, int n, int threshold)
{
    int c = 0;
    for (int i = 0; i < n; i++) c += (rgba[i*4 + 3] >= threshold);
    return (double)c/n;
}

// Foliage-like cut-out: thin opaque blades (1-2 texels wide) with soft edges on transparent ground.
// Plain mips average the blades away (coverage falls level by level); preserved mips keep level 0's
// share to the best the level's alpha histogram allows, which the test finds by brute force over
// every 8-bit boundary of the plain level (the same chain: preservation scales alpha after a level
// has served as the next one's source).
static void test_materials_alpha_coverage_is_kept_on_every_mip_level(void)
{
    const int w = 128, h = 128;
    Image albedo = GenImageColor(w, h, (Color){ 60, 140, 50, 0 });
    unsigned int seed = 77u;
    for (int b = 0; b < 60; b++)
    {
        float x0 = rtRandomRange(&seed, 0.0f, (float)w), y0 = rtRandomRange(&seed, 0.0f, (float)h);
        float ang = rtRandomRange(&seed, 0.0f, 6.2831853f), len = rtRandomRange(&seed, 10.0f, 40.0f);
        for (int s = 0; s < (int)(len*2.0f); s++)
        {
            int x = (int)(x0 + cosf(ang)*s*0.5f), y = (int)(y0 + sinf(ang)*s*0.5f);
            if ((x < 0) || (y < 0) || (x >= w) || (y >= h)) continue;
            ImageDrawPixel(&albedo, x, y, (Color){ 60, 140, 50, 255 });
            if (x + 1 < w) { Color c = GetImageColor(albedo, x + 1, y); if (c.a < 160) ImageDrawPixel(&albedo, x + 1, y, (Color){ 60, 140, 50, 160 }); }
        }
    }
    const float cutoff = 0.5f;
    const int t = 128;              // 8-bit threshold of 0.5: a/255 >= 0.5
    RblMaterialSource src = sourceOf(albedo);
    src.mipmaps = true;
    RblPackedMaterial plain, kept;
    RT_CHECK(RblPackMaterial(&src, &plain), "plain pack");
    src.alphaCoverage = cutoff;
    RT_CHECK(RblPackMaterial(&src, &kept), "coverage pack");
    if ((plain.albedo.data == NULL) || (kept.albedo.data == NULL)) return;
    RT_CHECK(plain.albedo.mipmaps == kept.albedo.mipmaps, "mip counts differ");
    int lw, lh;
    double share0 = covShare((const unsigned char *)plain.albedo.data, w*h, t);
    double worstPlain = 0.0, worstKept = 0.0, worstGap = 0.0;
    int rgbChanged = 0;
    printf("    level  size     coverage plain  kept   (level 0: %.4f; best reachable)\n", share0);
    for (int level = 0; level < plain.albedo.mipmaps; level++)
    {
        size_t off = mipOffset(w, h, 4, level, &lw, &lh);
        const unsigned char *pl = (const unsigned char *)plain.albedo.data + off, *kp = (const unsigned char *)kept.albedo.data + off;
        int n = lw*lh;
        for (int i = 0; i < n; i++) rgbChanged += (memcmp(pl + i*4, kp + i*4, 3) != 0);
        double sp = covShare(pl, n, t), sk = covShare(kp, n, t);
        // Brute force: every boundary k (texels with plain alpha >= k pass), the share nearest level 0's
        double best = 1e9, bestShare = 0.0;
        for (int k = 1; k <= 255; k++) { double s = covShare(pl, n, k); if (fabs(s - share0) < best) { best = fabs(s - share0); bestShare = s; } }
        if (level == 0) RT_CHECK(memcmp(pl, kp, (size_t)n*4) == 0, "level 0 changed");
        else
        {
            worstPlain = fmax(worstPlain, fabs(sp - share0));
            worstKept = fmax(worstKept, fabs(sk - share0));
            worstGap = fmax(worstGap, fabs(fabs(sk - share0) - best));
            RT_CHECK(fabs(fabs(sk - share0) - best) < 1e-12, "level %d: kept coverage %.4f, the best reachable is %.4f (target %.4f)", level, sk, bestShare, share0);
        }
        printf("    %5d  %3dx%-3d  %.4f          %.4f (%.4f)\n", level, lw, lh, sp, sk, bestShare);
    }
    RT_CHECK(rgbChanged == 0, "%d texels changed colour (only alpha may change)", rgbChanged);
    RT_CHECK(worstPlain > 0.05, "plain mips kept coverage within %.4f: the case does not exercise the problem", worstPlain);
    printf("    worst |coverage - level 0| over levels 1..: plain %.4f, kept %.4f (best reachable: gap %.2g)\n", worstPlain, worstKept, worstGap);
    // Bad values are refused (NaN, negative, 1 or more)
    const float bad[3] = { NAN, -0.1f, 1.0f };
    for (int i = 0; i < 3; i++)
    {
        src.alphaCoverage = bad[i];
        RblPackedMaterial untouched;
        memset(&untouched, 0xA5, sizeof(untouched));
        matWarnings = 0;
        SetTraceLogCallback(matCountingLog);
        bool ok = RblPackMaterial(&src, &untouched);
        SetTraceLogCallback(NULL);
        unsigned char probe[sizeof(untouched)];
        memset(probe, 0xA5, sizeof(probe));
        RT_CHECK(!ok && (matWarnings == 1) && (memcmp(&untouched, probe, sizeof(probe)) == 0), "alphaCoverage %g accepted or output written (%d warnings)", bad[i], matWarnings);
    }
    RblUnloadPackedMaterial(&plain);
    RblUnloadPackedMaterial(&kept);
    UnloadImage(albedo);
}
