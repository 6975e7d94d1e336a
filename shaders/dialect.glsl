// Dialect: the few words that differ between GLSL 330 (desktop GL 3.3+), GLSL ES 3.00 (ES 3, WebGL2),
// GLSL 1.20 (GL 2.1) and GLSL ES 1.00 (ES 2, WebGL1). The loader writes the #version line and
// RBL_GLSL (330, 300, 120 or 100), RBL_GLSL_ES on ES, and RBL_VERTEX_STAGE or RBL_FRAGMENT_STAGE
// before any source; every other file writes these words instead. Included first (by common.glsl,
// fullscreen.vs.glsl and volume.vs.glsl); includes nothing.
//   RBL_ATTRIBUTE          a vertex input
//   RBL_VARYING            a vertex output / fragment input
//   RBL_FLAT               not interpolated (1.x dialects have no flat: such values are constant anyway)
//   rblFetch(map, at, n)   texel `at` (ivec2) of an n x n texture, unfiltered
//   RBL_DERIVATIVES        dFdx/dFdy exist in this fragment stage (GLSL ES 1.00: OES_standard_derivatives)
// Instanced and deferred stages use GLSL 3 features (integer bits, MRT, layout locations): the loader
// compiles them only for 330 and 300 es.

#if defined(RBL_GLSL_ES) && (RBL_GLSL < 300) && defined(RBL_FRAGMENT_STAGE) && defined(GL_OES_standard_derivatives)
#extension GL_OES_standard_derivatives : enable
#endif
#if defined(RBL_FRAGMENT_STAGE) && ((RBL_GLSL >= 300) || !defined(RBL_GLSL_ES) || defined(GL_OES_standard_derivatives))
#define RBL_DERIVATIVES
#endif

#ifdef RBL_GLSL_ES
// Highp everywhere it exists: ES defaults samplers to lowp, which bands depth reads, and ES 2 may
// lack highp in the fragment stage (then mediump, the most it has)
#if (RBL_GLSL < 300) && defined(RBL_FRAGMENT_STAGE) && !defined(GL_FRAGMENT_PRECISION_HIGH)
precision mediump float;
precision mediump int;
#else
precision highp float;
precision highp int;
precision highp sampler2D;
#endif
#endif

#if RBL_GLSL >= 300
#define RBL_ATTRIBUTE in
#define RBL_FLAT flat
#ifdef RBL_VERTEX_STAGE
#define RBL_VARYING out
#else
#define RBL_VARYING in
#endif
#define rblFetch(map, at, n) texelFetch(map, at, 0)
#else
#define RBL_ATTRIBUTE attribute
#define RBL_VARYING varying
#define RBL_FLAT
#define texture texture2D
#define rblFetch(map, at, n) texture2D(map, (vec2(at) + 0.5)/(n))
#endif
