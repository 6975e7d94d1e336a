// The GPU suite's tests, one list for every runner: tests/test_gpu_main.c (EGL, OSMesa, ES 3, ES 2,
// GL 2.1) and tests/web/test_web_main.c (WebGL2, less the tests it states it leaves out). Needs the
// implementation, harness.h, gpu_common.h and the C headers included first.
#ifndef RBL_TESTS_GPU_TESTS_H
#define RBL_TESTS_GPU_TESTS_H

#include "reference.h"
#include "gpu_common.h"
#include "batch_peek.h"
#include "test_batch.c"
#include "test_api.c"
#include "test_instanced.c"
#include "test_material_render.c"
#include "test_lighting.c"
#include "test_deferred.c"
#include "test_view.c"
#include "test_shadows.c"
#include "test_self_shadow.c"
#include "test_omni_cascades.c"
#include "test_skinning.c"
#include "test_translucent.c"
#include "test_atlas_render.c"
#include "test_fade.c"
#include "test_held.c"
#include "test_sprite_buffer.c"
#include "test_thin.c"
#include "test_deferred_thin.c"
#include "test_cull.c"
#include "test_clustered.c"
#include "test_polygon.c"
#include "test_records.c"

static const RtTest rblGpuTests[] = {
        RBL_BATCH_TESTS,
        RBL_API_TESTS,
        RBL_INSTANCED_TESTS,
        RBL_MATERIAL_RENDER_TESTS,
        RBL_LIGHTING_TESTS,
        RBL_DEFERRED_TESTS,
        RBL_VIEW_TESTS,
        RBL_SHADOWS_TESTS,
        RBL_SELF_SHADOW_TESTS,
        RBL_OMNI_CASCADES_TESTS,
        RBL_SKINNING_TESTS,
        RBL_TRANSLUCENT_TESTS,
        RBL_ATLAS_RENDER_TESTS,
        RBL_FADE_TESTS,
        RBL_HELD_TESTS,
        RBL_SPRITE_BUFFER_TESTS,
        RBL_THIN_TESTS,
        RBL_DEFERRED_THIN_TESTS,
        RBL_CULL_TESTS,
        RBL_CLUSTERED_TESTS,
        RBL_POLYGON_TESTS,
        RBL_RECORDS_TESTS,
    };
#define RBL_GPU_TEST_COUNT ((int)(sizeof(rblGpuTests)/sizeof(rblGpuTests[0])))

#endif
