// The 0.3 baseline of bench_geometry (bench_geometry_v03.c): its own header copy, its own types;
// only raylib types cross this interface
#ifndef BENCH_GEOMETRY_V03_H
#define BENCH_GEOMETRY_V03_H
#include "raylib.h"
#include <stdbool.h>
#include <stddef.h>

bool V03Init(Texture2D atlas, int capacity, Vector3 lightPosition, float lightIntensity, Color ambient); // false: no 0.3 header built in, or load failed
void V03SetCard(int set, int i, Vector3 position, Vector2 size, Vector2 origin, float rotation, Rectangle source); // CAMERA_PLANE, up +Y, WHITE
int V03Frame(Camera3D camera, int set, int n, double (*now)(void), double *afterAdds); // 0.3 RblBeginBatch, n RblBatchAdd, RblEndBatch; billboards added
size_t V03BillboardSize(void);      // sizeof 0.3's RblBillboard (0 = not built in)
size_t V03VertexSize(void);         // sizeof 0.3's RblVertex
void V03Close(void);
#endif
