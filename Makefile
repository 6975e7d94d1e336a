# rbillboard_lit.h - build, test, run and benchmark.
#   make run     the showcase (a window when a display exists, else build/showcase.png)
#   make test    every test, headless (EGL GL 3.3, OSMesa, strict ES 3.0 / ES 2.0 / GL 2.1); ends with "N passed, N failed"
#   make bench   benchmarks (-O2) -> build/bench/results.csv and a table
#   make shaders splice shaders/*.glsl into rbillboard_lit.h
#   make web     the showcase as a page: build/web/index.html (WebGL2, WebGL1 fallback build)
#   make test-web  the browser GPU suite in headless Chromium; ends with "web: N passed, N failed"
#   make test-page the showcase page's checks in headless Chromium (sizes, input, context loss, no WebGL)
#   make raylib-master  clone raylib master into build/raylib-master: make test then also compiles the
#                header, README code and examples against its headers (or RAYLIB_MASTER=<tree>)
# raylib >= 6.0 is found by tests/tools/get-raylib.sh: pkg-config, then RAYLIB_SRC=<tree>, then
# Debian's source package (built once into build/raylib).

BUILD    ?= build
CC       ?= cc
WARN     := -Wall -Wextra -pedantic -Werror
CSTD     := -std=c99 -D_DEFAULT_SOURCE
TEST_CFLAGS  := $(CSTD) $(WARN) -O1 -g -I. -Itests -DRBL_INSTRUMENTS
BENCH_CFLAGS := $(CSTD) $(WARN) -O2 -I. -Itests -DRBL_INSTRUMENTS
SAN      := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined

.PHONY: all run quickstart test test-quick bench shaders check-shaders pictures clean clean-all deps web test-web test-page web-deps web-shot api-index raylib-master
all: test

# ---- raylib (located or built once; the result is cached in $(BUILD)/raylib.mk) -----------
NO_RAYLIB_GOALS := clean clean-all shaders check-shaders deps api-index raylib-master
ifeq ($(filter $(NO_RAYLIB_GOALS),$(MAKECMDGOALS)),)
include $(BUILD)/raylib.mk
endif
# raylib.mk records the RAYLIB_SRC it was made for; another one remakes it. Through a phony
# prerequisite, never by declaring raylib.mk itself phony: make does not re-read a phony makefile
# it remade, so the recipes ran without raylib's flags (a fresh clone's first
# `make run RAYLIB_SRC=...` failed with raylib.h not found)
ifneq ($(RAYLIB_FOUND_FOR),$(RAYLIB_SRC))
RAYLIB_MK_AGAIN := raylib-mk-again
endif
.PHONY: raylib-mk-again
raylib-mk-again:

# Remade when get-raylib.sh changes (its build flags are in the stamp: an older build is rebuilt)
$(BUILD)/raylib.mk: tests/tools/get-raylib.sh $(RAYLIB_MK_AGAIN)
	@mkdir -p $(BUILD)
	@bash tests/tools/deps.sh
	@BUILD=$(BUILD) RAYLIB_SRC="$(RAYLIB_SRC)" bash tests/tools/get-raylib.sh > $@.tmp || { rm -f $@.tmp; exit 1; }
	@echo "RAYLIB_FOUND_FOR := $(RAYLIB_SRC)" >> $@.tmp
	@mv $@.tmp $@

deps:
	@bash tests/tools/deps.sh

# The README's API index, regenerated from the header's declarations (make test checks it)
api-index:
	@bash tests/tools/api_index.sh write rbillboard_lit.h README.md
	@echo "api-index: README.md rewritten from rbillboard_lit.h"

# ---- shaders ------------------------------------------------------------------------------
shaders:
	@bash shaders/embed.sh rbillboard_lit.h
	@echo "shaders: rbillboard_lit.h is up to date with shaders/"

check-shaders:
	@bash shaders/embed.sh rbillboard_lit.h $(BUILD)/rbillboard_lit.check.h && cmp -s $(BUILD)/rbillboard_lit.check.h rbillboard_lit.h \
	  || { echo "check-shaders: rbillboard_lit.h differs from shaders/ (run make shaders)"; exit 1; }

# ---- tests --------------------------------------------------------------------------------
# The showcase page's files (built in the browser section below; named here, before `test` reads them)
WEB_PAGE_FILES := $(BUILD)/web/showcase.js $(BUILD)/web/showcase-gl1.js $(BUILD)/web/index.html $(BUILD)/web/page_check.html $(BUILD)/web/shell.html $(BUILD)/web/game.js
WEB_PAGE_MODES := main "dpr --force-device-scale-factor=2" "gl1 --disable-webgl2" "nowebgl --disable-webgl" shell "shellnowebgl --disable-webgl"
HEADER    := rbillboard_lit.h
HARNESS   := tests/harness.c tests/harness.h
CPU_TESTS := tests/test_geometry.c tests/test_materials.c tests/test_shaders_source.c tests/reference.h tests/degenerate.h tests/test_atlas.c
GPU_TESTS := tests/gpu_tests.h tests/test_api.c tests/test_batch.c tests/test_instanced.c tests/test_material_render.c tests/test_lighting.c tests/test_deferred.c tests/test_view.c tests/test_shadows.c tests/test_self_shadow.c tests/test_omni_cascades.c tests/test_skinning.c tests/skin_rig.h tests/reference.h tests/lighting_reference.h tests/degenerate.h tests/tf_capture.h tests/test_translucent.c tests/test_atlas_render.c tests/test_fade.c tests/test_held.c tests/test_sprite_buffer.c tests/test_cull.c tests/test_thin.c tests/test_deferred_thin.c tests/test_clustered.c tests/test_polygon.c tests/test_records.c tests/batch_peek.h

$(BUILD)/tests/test_cpu: tests/test_cpu_main.c $(CPU_TESTS) $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(RAYLIB_CFLAGS) tests/test_cpu_main.c tests/harness.c -o $@ $(RAYLIB_LIBS)

$(BUILD)/tests/test_cpu_san: tests/test_cpu_main.c $(CPU_TESTS) $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(RAYLIB_CFLAGS) tests/test_cpu_main.c tests/harness.c -o $@ $(RAYLIB_LIBS)

# The GPU suites run under ASan+UBSan (desktop and ES 3): a test or path reading past a buffer
# fails there rather than flaking (about +12 s a context)
$(BUILD)/tests/test_gpu: tests/test_gpu_main.c $(GPU_TESTS) $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(RAYLIB_CFLAGS) tests/test_gpu_main.c tests/harness.c -o $@ $(RAYLIB_LIBS)

$(BUILD)/tests/test_api_san: tests/test_api_main.c tests/test_api.c $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(RAYLIB_CFLAGS) tests/test_api_main.c tests/harness.c -o $@ $(RAYLIB_LIBS)

# Contract suite: small limits so that they are reached in a few draws (the checks are the same code)
CONTRACT_LIMITS := -DRBL_MAX_BATCH_BILLBOARDS=64 -DRBL_MAX_INSTANCES=64 -DRBL_MAX_SCENE_LIGHTS=256 -DRBL_MAX_ATLAS_ENTRIES=4096
$(BUILD)/tests/test_contracts: tests/test_contracts.c tests/gpu_common.h tests/skin_rig.h $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(CONTRACT_LIMITS) $(RAYLIB_CFLAGS) tests/test_contracts.c tests/harness.c -o $@ $(RAYLIB_LIBS)

$(BUILD)/tests/test_alloc: tests/test_alloc.c tests/gpu_common.h $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(RAYLIB_CFLAGS) tests/test_alloc.c tests/harness.c -o $@ $(RAYLIB_LIBS)

# Teardown orders with a real raylib window (xvfb-run in tests/run.sh): C99 and C++11 (RAII holders)
$(BUILD)/tests/test_teardown: tests/test_teardown.c $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(RAYLIB_CFLAGS) $< -o $@ $(RAYLIB_LIBS)

$(BUILD)/tests/test_teardown_cpp: tests/test_teardown.c $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CXX) -std=c++11 $(WARN) -O1 -g -I. -Itests $(SAN) $(RAYLIB_CFLAGS) -x c++ $< -x none -o $@ $(RAYLIB_LIBS)

# The GPU suite against raylib built for ES 3, ES 2 and GL 2.1 (tests/tools/raylib-variant.sh builds
# each once from the same source tree; the harness makes the context itself)
GPU_CONTEXTS := gles3 gles2 gl21
$(BUILD)/raylib-%/libraylib.a: tests/tools/raylib-variant.sh $(BUILD)/raylib.mk
	@BUILD=$(BUILD) RAYLIB_SRC="$(RAYLIB_SRC)" bash tests/tools/raylib-variant.sh $*

# Per context: its raylib build folder, GL library and sanitizers (ES 3 under ASan+UBSan, as before;
# ES 2 and GL 2.1 without)
VARIANT_DIR_gles3 := raylib-es3
VARIANT_DIR_gles2 := raylib-es2
VARIANT_DIR_gl21  := raylib-gl21
VARIANT_GL_gles3  := -lGLESv2
VARIANT_GL_gles2  := -lGLESv2
VARIANT_GL_gl21   := -lGL
VARIANT_SAN_gles3 := $(SAN)
VARIANT_FLAGS = -I$(BUILD)/$(VARIANT_DIR_$*) -DSUPPORT_GPU_SKINNING=1
VARIANT_LIBS = $(BUILD)/$(VARIANT_DIR_$*)/libraylib.a $(VARIANT_GL_$*) -lm -lpthread -ldl
.SECONDEXPANSION:
$(addprefix $(BUILD)/tests/test_gpu_,$(GPU_CONTEXTS)): $(BUILD)/tests/test_gpu_%: tests/test_gpu_main.c $(GPU_TESTS) $(HARNESS) $(HEADER) $(BUILD)/$$(VARIANT_DIR_$$*)/libraylib.a
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(VARIANT_SAN_$*) $(VARIANT_FLAGS) tests/test_gpu_main.c tests/harness.c -o $@ $(VARIANT_LIBS)

# Atlas readers under libFuzzer (clang; libclang-rt-dev), one binary per format; tests/run.sh runs
# each for a bounded time over its hand-written seed corpus (tests/fuzz/corpus/<format>/)
FUZZ_FORMATS := texturepacker aseprite libgdx
FUZZ_CFLAGS := $(CSTD) $(WARN) -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I. $(RAYLIB_CFLAGS)
$(BUILD)/fuzz/atlas_impl.o: tests/fuzz/fuzz_atlas.c $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	clang $(FUZZ_CFLAGS) -DFUZZ_IMPL -c tests/fuzz/fuzz_atlas.c -o $@
$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_atlas.c $(BUILD)/fuzz/atlas_impl.o
	clang $(FUZZ_CFLAGS) -DFUZZ_FORMAT=RBL_ATLAS_$(shell echo $* | tr a-z A-Z) tests/fuzz/fuzz_atlas.c $(BUILD)/fuzz/atlas_impl.o -o $@ $(RAYLIB_LIBS)

# Every stage as the loader splices it, in every dialect, for glslangValidator (tests/run.sh)
$(BUILD)/tests/splice_shaders: tests/tools/splice_shaders.c $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(RAYLIB_CFLAGS) tests/tools/splice_shaders.c -o $@ $(RAYLIB_LIBS)

test: $(addprefix $(BUILD)/fuzz/fuzz_,$(FUZZ_FORMATS)) $(BUILD)/tests/splice_shaders $(addprefix $(BUILD)/tests/test_gpu_,$(GPU_CONTEXTS)) $(BUILD)/tests/test_cpu $(BUILD)/tests/test_cpu_san $(BUILD)/tests/test_api_san $(BUILD)/tests/test_contracts $(BUILD)/tests/test_alloc $(BUILD)/tests/test_teardown $(BUILD)/tests/test_teardown_cpp $(BUILD)/tests/test_gpu $(BUILD)/showcase $(BUILD)/deferred $(BUILD)/deferred_headless $(BUILD)/sprites_headless $(BUILD)/game_headless $(BUILD)/readme_run $(BUILD)/web/test/test_web.js $(WEB_PAGE_FILES)
	@BUILD=$(BUILD) RAYLIB_CFLAGS="$(RAYLIB_CFLAGS)" RAYLIB_LIBS="$(RAYLIB_LIBS)" RAYLIB_MASTER="$(RAYLIB_MASTER)" bash tests/run.sh

# The edit loop: the CPU suite, the contracts, the GPU suite on EGL, the API index and the README's
# programs (tests/run_quick.sh); make test runs everything
test-quick: $(BUILD)/tests/test_cpu $(BUILD)/tests/test_contracts $(BUILD)/tests/test_gpu $(BUILD)/readme_run
	@BUILD=$(BUILD) bash tests/run_quick.sh

# raylib master's source for make test's optional check against its headers (needs the network;
# under $(BUILD), so never committed). RAYLIB_MASTER=<tree> names one already on disk instead.
raylib-master:
	@if [ -d $(BUILD)/raylib-master/.git ]; then git -C $(BUILD)/raylib-master pull -q --ff-only; \
	 else git clone -q --depth 1 https://github.com/raysan5/raylib $(BUILD)/raylib-master; fi
	@echo "raylib-master: $(BUILD)/raylib-master at $$(git -C $(BUILD)/raylib-master log -1 --format='%h %cs')"

# ---- showcase -----------------------------------------------------------------------------
# Each example rendered headlessly by its tool (tests/tools/<name>_headless.c includes the example)
$(BUILD)/showcase_headless: examples/shaders_lit_billboards.c
$(BUILD)/deferred_headless: examples/shaders_deferred_billboards.c
$(BUILD)/sprites_headless: examples/shaders_lit_sprite_sheet.c
$(BUILD)/game_headless: examples/shaders_lit_sprite_game.c
$(BUILD)/%_headless: tests/tools/%_headless.c $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) $< tests/harness.c -o $@ $(RAYLIB_LIBS)

$(BUILD)/showcase: examples/shaders_lit_billboards.c $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) $< -o $@ $(RAYLIB_LIBS)

$(BUILD)/deferred: examples/shaders_deferred_billboards.c $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) $< -o $@ $(RAYLIB_LIBS)

run: $(BUILD)/showcase $(BUILD)/showcase_headless
	@if [ -n "$$DISPLAY" ] && { command -v xdpyinfo >/dev/null 2>&1 && xdpyinfo >/dev/null 2>&1 || [ -S /tmp/.X11-unix/X$${DISPLAY#*:} ]; }; then \
	  cd examples && ../$(BUILD)/showcase; \
	else \
	  echo "run: no display; rendering the showcase headlessly"; \
	  $(BUILD)/showcase_headless $(BUILD)/showcase.png; \
	fi

# The README's code as printed: the quick start and every how-to, run headlessly (make test checks
# each picture); make quickstart builds the quick start alone and runs it in examples/ (a window when
# a display exists, else build/quickstart.png through the headless runner)
$(BUILD)/tests/readme_code.inc: README.md tests/tools/readme_code.sh
	@mkdir -p $(@D)
	@bash tests/tools/readme_code.sh README.md $@

$(BUILD)/readme_run: tests/tools/readme_run.c $(BUILD)/tests/readme_code.inc $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(SAN) $(RAYLIB_CFLAGS) -I$(BUILD)/tests tests/tools/readme_run.c tests/harness.c -o $@ $(RAYLIB_LIBS)

$(BUILD)/quickstart.c: README.md
	@mkdir -p $(@D)
	@awk '/^<!-- run: quickstart -->$$/ {m=1; next} m && /^```c$$/ {f=1; next} f && /^```$$/ {exit} f' README.md > $@

$(BUILD)/quickstart: $(BUILD)/quickstart.c $(HEADER) $(BUILD)/raylib.mk
	$(CC) $(BENCH_CFLAGS) -I. $(RAYLIB_CFLAGS) $< -o $@ $(RAYLIB_LIBS)

quickstart: $(BUILD)/quickstart $(BUILD)/readme_run
	@if [ -n "$$DISPLAY" ] && { command -v xdpyinfo >/dev/null 2>&1 && xdpyinfo >/dev/null 2>&1 || [ -S /tmp/.X11-unix/X$${DISPLAY#*:} ]; }; then \
	  cd examples && $(abspath $(BUILD))/quickstart; \
	else \
	  echo "quickstart: no display; running it headlessly"; \
	  cd examples && ASAN_OPTIONS=detect_leaks=0 $(abspath $(BUILD))/readme_run $(abspath $(BUILD)) | grep quickstart; \
	fi

# ---- benchmarks ---------------------------------------------------------------------------
# One rule for every suite's binary (tests/bench/bench_<suite>.c); the headers a suite shares with
# the tests are named as extra prerequisites
$(addprefix $(BUILD)/bench/bench_,lighting deferred shadows): tests/lighting_reference.h tests/reference.h
$(BUILD)/bench/bench_skinning: tests/skin_rig.h
$(BUILD)/bench/bench_deferred $(BUILD)/bench/bench_clustered: tests/bench/bench_floor.h
$(BUILD)/bench/bench_thin $(BUILD)/bench/bench_deferred_thin: tests/relief_reference.h tests/reference.h
$(BUILD)/bench/bench_%: tests/bench/bench_%.c tests/bench/bench.h $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) $< tests/harness.c -o $@ $(RAYLIB_LIBS)

# bench_geometry's 0.3 baseline: that header (the commit before the 0.4 API change) from git history,
# compiled in its own translation unit; without the history the baseline rows are left out
BENCH_V03_COMMIT := ba3c89d~1
$(BUILD)/bench/v03/bench_geometry_v03.o: tests/bench/bench_geometry_v03.c tests/bench/bench_geometry_v03.h $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	@if git show $(BENCH_V03_COMMIT):rbillboard_lit.h > $(@D)/rbillboard_lit.h 2>/dev/null; then \
	  echo "$(CC) ... bench_geometry_v03.c (0.3 header from $(BENCH_V03_COMMIT))"; \
	  $(CC) $(CSTD) -O2 -Wall -Wextra -Werror -Wno-unused-function -I$(@D) -Itests/bench $(RAYLIB_CFLAGS) -c $< -o $@; \
	else echo "bench_geometry: no git history for the 0.3 baseline; its rows are left out"; \
	  $(CC) $(BENCH_CFLAGS) -DBENCH_NO_V03 -Itests/bench $(RAYLIB_CFLAGS) -c $< -o $@; fi

$(BUILD)/bench/bench_geometry: tests/bench/bench_geometry.c tests/bench/bench.h tests/bench/bench_geometry_v03.h $(BUILD)/bench/v03/bench_geometry_v03.o $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) tests/bench/bench_geometry.c tests/harness.c $(BUILD)/bench/v03/bench_geometry_v03.o -o $@ $(RAYLIB_LIBS)

# bench_api: one binary from three compilations of bench_api.c (main, the showcase and the deferred example,
# each example with its own copy of the header) plus bench_api_gl.h, the counting wrappers of every glad_gl*
# pointer, generated from raylib's external/glad.h (without one the GL-call rows are skipped)
BENCH_API_GLAD := $(abspath $(firstword $(wildcard $(RAYLIB_SRC)/src/external/glad.h $(BUILD)/raylib-src/*/src/external/glad.h)))
BENCH_API_EXAMPLES := examples/shaders_lit_billboards.c examples/shaders_deferred_billboards.c
$(BUILD)/bench/bench_api: tests/bench/bench_api.c tests/bench/bench.h $(BENCH_API_EXAMPLES) $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) -DBENCH_API_GEN tests/bench/bench_api.c -o $(@D)/bench_api_gen
	$(@D)/bench_api_gen "$(BENCH_API_GLAD)" "$(if $(BENCH_API_GLAD),$(dir $(BENCH_API_GLAD))../rlgl.h)" > $(@D)/bench_api_gl.h
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) -DBENCH_API_PART=1 -c tests/bench/bench_api.c -o $(@D)/bench_api_showcase.o
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) -DBENCH_API_PART=2 -c tests/bench/bench_api.c -o $(@D)/bench_api_deferred.o
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) -I$(@D) -DBENCH_API_GL tests/bench/bench_api.c $(@D)/bench_api_showcase.o $(@D)/bench_api_deferred.o tests/harness.c -o $@ $(RAYLIB_LIBS)

# Suite `platforms`: one binary per graphics API (the desktop raylib, then the variants), each run on
# its strict context by tests/bench/run.sh
PF_DEPS := tests/bench/bench_platforms.c tests/bench/bench.h examples/shaders_lit_billboards.c $(HARNESS) $(HEADER)
$(BUILD)/bench/bench_platforms_egl: $(PF_DEPS) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) tests/bench/bench_platforms.c tests/harness.c -o $@ $(RAYLIB_LIBS)
$(addprefix $(BUILD)/bench/bench_platforms_,$(GPU_CONTEXTS)): $(BUILD)/bench/bench_platforms_%: $(PF_DEPS) $(BUILD)/$$(VARIANT_DIR_$$*)/libraylib.a
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(VARIANT_FLAGS) tests/bench/bench_platforms.c tests/harness.c -o $@ $(VARIANT_LIBS)

bench: $(BUILD)/bench/bench_blend $(addprefix $(BUILD)/bench/bench_platforms_,egl $(GPU_CONTEXTS)) $(BUILD)/bench/bench_geometry $(BUILD)/bench/bench_materials $(BUILD)/bench/bench_lighting $(BUILD)/bench/bench_deferred $(BUILD)/bench/bench_clustered $(BUILD)/bench/bench_shadows $(BUILD)/bench/bench_thin $(BUILD)/bench/bench_deferred_thin $(BUILD)/bench/bench_overdraw $(BUILD)/bench/bench_skinning $(BUILD)/bench/bench_sprites $(BUILD)/bench/bench_polygon $(BUILD)/bench/bench_api
	@BUILD=$(BUILD) bash tests/bench/run.sh

clean:
	rm -rf $(BUILD)/tests $(BUILD)/bench $(BUILD)/test-output $(BUILD)/cmake_consumer_* $(BUILD)/cmake_readme_* $(BUILD)/setup_check $(BUILD)/raylib_examples $(BUILD)/showcase $(BUILD)/showcase_headless $(BUILD)/showcase.png \
	  $(BUILD)/deferred $(BUILD)/deferred_headless $(BUILD)/deferred.png $(BUILD)/deferred_views.png \
	  $(BUILD)/sprites_headless $(BUILD)/sprites.png $(BUILD)/game_headless $(BUILD)/game.png

clean-all:
	rm -rf $(BUILD)

# ---- browser (Debian's emscripten 3.1.6 + headless Chromium, both from tests/tools/deps.sh web) ----
# raylib is built for PLATFORM_WEB_RGFW twice (ES 3 for WebGL2, ES 2 for the WebGL1 fallback) into
# $(BUILD)/web/raylib-es3|es2 from the source tree get-raylib.sh fetched. emcc writes .js + .wasm only
# (its -o page.html minifier crashes on Debian's node): the pages are tests/web/*.html.
WEB_SHOWCASE := examples/shaders_lit_billboards.c
WEBCC        := NODE_PATH=/usr/share/nodejs emcc
WEB_CFLAGS   := $(CSTD) $(WARN) -O2 -I. -Itests -DSUPPORT_GPU_SKINNING=1 -DRBL_INSTRUMENTS
WEB_LDFLAGS  := -sALLOW_MEMORY_GROWTH=1 -sTOTAL_STACK=16777216 -sINITIAL_MEMORY=67108864
WEB_ES3      := $(BUILD)/web/raylib-es3/libraylib.web.a
WEB_ES2      := $(BUILD)/web/raylib-es2/libraylib.web.a

web-deps:
	@bash tests/tools/deps.sh web

$(WEB_ES3): tests/tools/get-raylib-web.sh $(BUILD)/raylib.mk | web-deps
	@rm -f $@
	@BUILD=$(BUILD) RAYLIB_SRC="$(RAYLIB_SRC)" bash tests/tools/get-raylib-web.sh es3

$(WEB_ES2): tests/tools/get-raylib-web.sh $(BUILD)/raylib.mk | web-deps
	@rm -f $@
	@BUILD=$(BUILD) RAYLIB_SRC="$(RAYLIB_SRC)" bash tests/tools/get-raylib-web.sh es2

# The showcase page: WebGL2 build (showcase.js) and WebGL1 build (showcase-gl1.js); index.html loads
# the first when the browser gives a WebGL2 context, else the second
$(BUILD)/web/showcase.js: tests/web/showcase_web.c $(WEB_SHOWCASE) $(HEADER) $(WEB_ES3) | web-deps
	@mkdir -p $(@D)
	$(WEBCC) $(WEB_CFLAGS) -DRBL_WEB_SHOWCASE='"../../$(WEB_SHOWCASE)"' -DRBL_WEB_GL=2 -I$(BUILD)/web/raylib-es3 $< $(WEB_ES3) -o $@ \
	  $(WEB_LDFLAGS) -sUSE_WEBGL2=1 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2

$(BUILD)/web/showcase-gl1.js: tests/web/showcase_web.c $(WEB_SHOWCASE) $(HEADER) $(WEB_ES2) | web-deps
	@mkdir -p $(@D)
	$(WEBCC) $(WEB_CFLAGS) -DRBL_WEB_SHOWCASE='"../../$(WEB_SHOWCASE)"' -DRBL_WEB_GL=1 -I$(BUILD)/web/raylib-es2 $< $(WEB_ES2) -o $@ \
	  $(WEB_LDFLAGS) -sMIN_WEBGL_VERSION=1 -sMAX_WEBGL_VERSION=1

$(BUILD)/web/index.html: tests/web/index.html
	@mkdir -p $(@D)
	cp $< $@

web: $(BUILD)/web/showcase.js $(BUILD)/web/showcase-gl1.js $(BUILD)/web/index.html
	@echo "web: open build/web/index.html through a web server (python3 -m http.server -d $(BUILD)/web)"

# The page's checks (tests/web/page_check.html; make test runs them): the showcase page in every
# mode, and the README's minimal shell as printed (shell.html) with the showcase build as game.js
$(BUILD)/web/page_check.html: tests/web/page_check.html
	@mkdir -p $(@D)
	cp $< $@
$(BUILD)/web/shell.html: README.md
	@mkdir -p $(@D)
	@awk '/^<!-- tested by tests\/web\/page_check.html \(shell\) -->$$/ {m=1; next} m && /^```html$$/ {f=1; next} f && /^```$$/ {exit} f' README.md > $@
	@test -s $@ || { echo "shell.html: README has no html block after its 'tested by' marker"; rm -f $@; exit 1; }
$(BUILD)/web/game.js: $(BUILD)/web/showcase.js
	cp $(BUILD)/web/showcase.js $@
	cp $(BUILD)/web/showcase.wasm $(BUILD)/web/game.wasm
test-page: $(WEB_PAGE_FILES)
	@for m in $(WEB_PAGE_MODES); do python3 tests/web/run.py page $(BUILD)/web $$m || exit 1; done

# Headless screenshots of the page for the README (SwiftShader WebGL2; and with no WebGL at all)
web-shot: web
	@python3 tests/web/run.py shot $(BUILD)/web examples/resources/rbl_web.png 800 450 6000
	@WEB_CHROMIUM_FLAGS=--disable-webgl python3 tests/web/run.py shot $(BUILD)/web examples/resources/rbl_web_nowebgl.png 640 360 2000

# The browser GPU suite: tests/web/test_web_main.c (tests/test_*.c are included whole: the ones not
# run in the browser are unused there, hence -Wno-unused-function)
$(BUILD)/web/test/test_web.js: tests/web/test_web_main.c tests/web/test.html $(GPU_TESTS) tests/gpu_common.h $(HARNESS) $(HEADER) $(WEB_ES3) | web-deps
	@mkdir -p $(@D)
	$(WEBCC) $(WEB_CFLAGS) -Wno-unused-function -I$(BUILD)/web/raylib-es3 tests/web/test_web_main.c tests/harness.c $(WEB_ES3) -o $@ \
	  $(WEB_LDFLAGS) -sUSE_WEBGL2=1 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sEXIT_RUNTIME=1
	cp tests/web/test.html $(@D)/index.html

test-web: $(BUILD)/web/test/test_web.js
	@python3 tests/web/run.py test $(BUILD)/web/test "$(WEB_FILTER)"

# ---- README pictures (rendered headlessly, committed under examples/resources) and the examples'
# screenshots (examples/<name>.png, 800x450, as raylib's examples/<module>/<name>.png) ------------
$(BUILD)/pictures: tests/tools/pictures.c $(HARNESS) $(HEADER) $(BUILD)/raylib.mk
	@mkdir -p $(@D)
	$(CC) $(BENCH_CFLAGS) $(RAYLIB_CFLAGS) tests/tools/pictures.c tests/harness.c -o $@ $(RAYLIB_LIBS)

pictures: $(BUILD)/pictures $(BUILD)/deferred_headless $(BUILD)/sprites_headless $(BUILD)/game_headless $(BUILD)/readme_run run
	@mkdir -p examples/resources
	@cd examples && ASAN_OPTIONS=detect_leaks=0 $(abspath $(BUILD))/readme_run resources | sed -n 's/^    wrote /pictures: wrote examples\//p'
	@$(BUILD)/pictures examples/resources
	@cp $(BUILD)/showcase.png examples/resources/rbl_showcase.png 2>/dev/null && echo "pictures: wrote examples/resources/rbl_showcase.png" || true
	@$(BUILD)/deferred_headless examples/resources/rbl_deferred.png examples/resources/rbl_deferred_views.png
	@cp examples/resources/rbl_showcase.png examples/shaders_lit_billboards.png && echo "pictures: wrote examples/shaders_lit_billboards.png"
	@cp examples/resources/rbl_deferred.png examples/shaders_deferred_billboards.png && echo "pictures: wrote examples/shaders_deferred_billboards.png"
	@$(BUILD)/sprites_headless examples/shaders_lit_sprite_sheet.png | sed 's/^/pictures: /'
	@$(BUILD)/game_headless examples/shaders_lit_sprite_game.png examples | sed 's/^/pictures: /'
	@cp examples/shaders_lit_sprite_game.png examples/resources/rbl_game.png && echo "pictures: wrote examples/resources/rbl_game.png"
