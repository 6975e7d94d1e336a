// bench_geometry's baseline: the batched path of rbillboard_lit.h 0.3 (the commit before the 0.4
// API change, ba3c89d~1), compiled into this translation unit alone with every public function
// static (RBLAPI), so the current header and 0.3 run in one process, in the same rounds. The 0.3
// header is extracted by the Makefile (git show) into $(BUILD)/bench/v03/; without it (no git
// history) BENCH_NO_V03 is defined and V03Init reports false.
#include "bench_geometry_v03.h"

#if !defined(BENCH_NO_V03)
#define RBLAPI static
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"     // 0.3, from $(BUILD)/bench/v03 (first on the include path)
#include <stdlib.h>
#include <string.h>

static RblLitShader v03Lit;
static Material v03Material;
static RblBatch v03Batch;
static RblBillboard *v03Sets[2];
static int v03Capacity;

bool V03Init(Texture2D atlas, int capacity, Vector3 lightPosition, float lightIntensity, Color ambient)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1;             // 0.3's default, as the current bench's lit program
    v03Lit = RblLoadLitShader(desc);
    RblLight light;
    memset(&light, 0, sizeof(light));
    light.position = lightPosition;
    light.color = WHITE;
    light.intensity = lightIntensity;
    if (!RblIsLitShaderValid(v03Lit) || !RblSetLights(&v03Lit, &light, 1, ambient)) return false;
    v03Material = LoadMaterialDefault();
    v03Material.shader = v03Lit.shader;
    v03Material.maps[MATERIAL_MAP_ALBEDO].texture = atlas;
    v03Batch = RblLoadBatch(capacity);
    for (int r = 0; r < 2; r++) v03Sets[r] = (RblBillboard *)calloc((size_t)capacity, sizeof(RblBillboard));
    v03Capacity = capacity;
    return RblIsBatchValid(v03Batch) && (v03Sets[0] != NULL) && (v03Sets[1] != NULL);
}

void V03SetCard(int set, int i, Vector3 position, Vector2 size, Vector2 origin, float rotation, Rectangle source)
{
    if ((set < 0) || (set > 1) || (i < 0) || (i >= v03Capacity)) return;
    RblBillboard *b = &v03Sets[set][i];
    memset(b, 0, sizeof(*b));
    b->position = position; b->size = size; b->origin = origin; b->rotation = rotation; b->source = source;
    b->tint = WHITE;
    b->facing = RBL_FACING_CAMERA_PLANE;
    b->up = (Vector3){ 0.0f, 1.0f, 0.0f };
}

int V03Frame(Camera3D camera, int set, int n, double (*now)(void), double *afterAdds)
{
    RblBeginBatch(&v03Batch, camera);
    int added = 0;
    for (int i = 0; i < n; i++) added += RblBatchAdd(&v03Batch, v03Material, &v03Sets[set][i]);
    *afterAdds = now();
    RblEndBatch(&v03Batch);
    return added;
}

size_t V03BillboardSize(void) { return sizeof(RblBillboard); }
size_t V03VertexSize(void) { return sizeof(RblVertex); }

void V03Close(void)
{
    RblUnloadBatch(&v03Batch);
    RblUnloadLitShader(v03Lit);
    MemFree(v03Material.maps);
    RblClose();
    for (int r = 0; r < 2; r++) free(v03Sets[r]);
}
#else
bool V03Init(Texture2D atlas, int capacity, Vector3 lightPosition, float lightIntensity, Color ambient)
{
    (void)atlas; (void)capacity; (void)lightPosition; (void)lightIntensity; (void)ambient;
    return false;
}
void V03SetCard(int set, int i, Vector3 position, Vector2 size, Vector2 origin, float rotation, Rectangle source)
{
    (void)set; (void)i; (void)position; (void)size; (void)origin; (void)rotation; (void)source;
}
int V03Frame(Camera3D camera, int set, int n, double (*now)(void), double *afterAdds) { (void)camera; (void)set; (void)n; *afterAdds = now(); return 0; }
size_t V03BillboardSize(void) { return 0; }
size_t V03VertexSize(void) { return 0; }
void V03Close(void) {}
#endif
