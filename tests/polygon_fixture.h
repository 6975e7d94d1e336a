// Hand-written polygon frames (TexturePacker polygon packing) on a 64 x 64 sheet, with the areas
// worked out by hand: the draw-path tests (test_polygon.c) and the CPU ones (test_atlas.c) read it.
//   diamond  upright 16 x 16 trim at (2, 4) of a 20 x 24 canvas, block (2, 2): the rhombus through the
//            trim's edge midpoints, 2 triangles, area 128 of the trim's 256 (the four corners cut away)
//   arrow    upright 20 x 12, untrimmed, block (24, 2): the concave arrowhead (0,0) (20,6) (0,12) (6,6),
//            area 84 of 240; its second triangle wound the other way, plus a degenerate one
//   rot      stored turned clockwise in the 12 x 20 block at (2, 24), upright 20 x 12: the triangle
//            (0,12) (20,12) (10,0), area 120 of 240; upright (x, y) lies at texel (2 + 12 - y, 24 + x)
#ifndef RBL_TESTS_POLYGON_FIXTURE_H
#define RBL_TESTS_POLYGON_FIXTURE_H

#define POLY_SHEET 64
static const char polyFixture[] =
    "{\"frames\": {"
    "\"diamond\": {\"frame\": {\"x\":2,\"y\":2,\"w\":16,\"h\":16}, \"rotated\": false, \"trimmed\": true,"
    " \"spriteSourceSize\": {\"x\":2,\"y\":4,\"w\":16,\"h\":16}, \"sourceSize\": {\"w\":20,\"h\":24},"
    " \"vertices\": [[10,4],[18,12],[10,20],[2,12]], \"verticesUV\": [[10,2],[18,10],[10,18],[2,10]], \"triangles\": [[0,1,2],[0,2,3]]},"
    "\"arrow\": {\"frame\": {\"x\":24,\"y\":2,\"w\":20,\"h\":12}, \"rotated\": false, \"trimmed\": false,"
    " \"spriteSourceSize\": {\"x\":0,\"y\":0,\"w\":20,\"h\":12}, \"sourceSize\": {\"w\":20,\"h\":12},"
    " \"vertices\": [[0,0],[20,6],[0,12],[6,6]], \"verticesUV\": [[24,2],[44,8],[24,14],[30,8]], \"triangles\": [[0,1,3],[3,2,1],[0,0,1]]},"
    "\"rot\": {\"frame\": {\"x\":2,\"y\":24,\"w\":20,\"h\":12}, \"rotated\": true, \"trimmed\": false,"
    " \"spriteSourceSize\": {\"x\":0,\"y\":0,\"w\":20,\"h\":12}, \"sourceSize\": {\"w\":20,\"h\":12},"
    " \"vertices\": [[0,12],[20,12],[10,0]], \"verticesUV\": [[2,24],[2,44],[14,34]], \"triangles\": [[0,1,2]]}"
    "}, \"meta\": {\"app\": \"https://www.codeandweb.com/texturepacker\", \"image\": \"poly.png\", \"size\": {\"w\":64,\"h\":64}, \"scale\": 1}}";
static const double polyFixtureArea[3] = { 128.0, 84.0, 120.0 };      // upright pixels, by hand (above)
static const int polyFixtureTriangles[3] = { 2, 2, 1 };                // non-degenerate triangles

// Whether upright frame pixel (x, y) lies in the polygon of frame k (0 diamond, 1 arrow, 2 rot) with
// a margin (> 0: inside by more than it; < 0: outside by more than -margin; distances in pixels to
// each triangle's edges, double precision), for the CPU rasterisation the render tests compare with
static inline int polyFixtureInside(int k, double x, double y, double margin)
{
    static const double tri[3][2][6] = {
        { { 8, 0, 16, 8, 8, 16 }, { 8, 0, 8, 16, 0, 8 } },            // diamond, in trim pixels
        { { 0, 0, 20, 6, 6, 6 }, { 6, 6, 20, 6, 0, 12 } },             // arrow
        { { 0, 12, 20, 12, 10, 0 }, { 0, 0, 0, 0, 0, 0 } } };          // rot
    // distance from p to the union: inside the union by d (min over its containing triangle's edges,
    // max over triangles) or outside by the distance to the nearest triangle
    double bestIn = -1e30, bestOut = 1e30;
    for (int t = 0; t < polyFixtureTriangles[k]; t++)
    {
        const double *v = tri[k][t];
        double area2 = (v[2] - v[0])*(v[5] - v[1]) - (v[4] - v[0])*(v[3] - v[1]);
        double sg = (area2 > 0.0)? 1.0 : -1.0, dIn = 1e30;
        bool in = true;
        for (int e = 0; e < 3; e++)
        {
            double ax = v[2*e], ay = v[2*e + 1], bx = v[(2*e + 2)%6], by = v[(2*e + 3)%6];
            double ex = bx - ax, ey = by - ay, len = sqrt(ex*ex + ey*ey);
            double d = sg*(ex*(y - ay) - ey*(x - ax))/len;      // signed distance, > 0 inside
            if (d < dIn) dIn = d;
            if (d < 0.0) in = false;
        }
        if (in && (dIn > bestIn)) bestIn = dIn;
        // outside distance: to the nearest point of the triangle (edges), approximated from below by -dIn when outside
        if (!in) { double o = -dIn; if (o < bestOut) bestOut = o; }
    }
    // (a point within margin of an edge two triangles share is neither: skipped, never misjudged)
    if (bestIn > -1e29) return (margin > 0.0)? (bestIn > margin) : 0;
    return (margin < 0.0)? (bestOut > -margin) : 0;
}
#endif
