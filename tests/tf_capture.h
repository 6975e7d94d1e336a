// Transform-feedback capture of the instanced vertex stage: runs lit_instanced.vs.glsl over
// instances with rasterisation discarded and returns what it emits (6 vertices per instance:
// fragPosition, fragTexCoord, fragNormal, fragTangent). Shared by the instanced tests and the
// geometry benchmark's accuracy rows. Needs the implementation (rbl__ helpers) and harness.h in
// the including file.
#ifndef RBL_TESTS_TF_CAPTURE_H
#define RBL_TESTS_TF_CAPTURE_H

typedef unsigned int GLu;
typedef struct {
    GLu (*CreateShader)(GLu);
    void (*ShaderSource)(GLu, int, const char *const *, const int *);
    void (*CompileShader)(GLu);
    void (*GetShaderiv)(GLu, GLu, int *);
    void (*GetShaderInfoLog)(GLu, int, int *, char *);
    GLu (*CreateProgram)(void);
    void (*AttachShader)(GLu, GLu);
    void (*TransformFeedbackVaryings)(GLu, int, const char *const *, GLu);
    void (*LinkProgram)(GLu);
    void (*GetProgramiv)(GLu, GLu, int *);
    void (*GenBuffers)(int, GLu *);
    void (*BindBuffer)(GLu, GLu);
    void (*BufferData)(GLu, ptrdiff_t, const void *, GLu);
    void (*BindBufferBase)(GLu, GLu, GLu);
    void (*Enable)(GLu);
    void (*Disable)(GLu);
    void (*BeginTransformFeedback)(GLu);
    void (*EndTransformFeedback)(void);
    void *(*MapBufferRange)(GLu, ptrdiff_t, ptrdiff_t, GLu);
    unsigned char (*UnmapBuffer)(GLu);
    void (*DeleteBuffers)(int, const GLu *);
    void (*DeleteProgram)(GLu);
    void (*DeleteShader)(GLu);
} TfGl;

static bool tfLoad(TfGl *gl)
{
    static const char *names[] = { "glCreateShader", "glShaderSource", "glCompileShader", "glGetShaderiv", "glGetShaderInfoLog",
        "glCreateProgram", "glAttachShader", "glTransformFeedbackVaryings", "glLinkProgram", "glGetProgramiv", "glGenBuffers",
        "glBindBuffer", "glBufferData", "glBindBufferBase", "glEnable", "glDisable", "glBeginTransformFeedback",
        "glEndTransformFeedback", "glMapBufferRange", "glUnmapBuffer", "glDeleteBuffers", "glDeleteProgram", "glDeleteShader" };
    void **slots = (void **)gl;     // TfGl is a sequence of pointers in the order of names[]
    for (size_t i = 0; i < sizeof(names)/sizeof(names[0]); i++)
    {
        void *p = rtGlProc(names[i]);
        if (p == NULL) { printf("    missing %s\n", names[i]); return false; }
        memcpy(&slots[i], &p, sizeof(p));
    }
    return true;
}

#define TF_FLOATS 12    // fragPosition (3), fragTexCoord (2), fragNormal (3), fragTangent (4)

static GLu tfShader(TfGl *gl, GLu type, const char *src)
{
    GLu sh = gl->CreateShader(type);
    gl->ShaderSource(sh, 1, &src, NULL);
    gl->CompileShader(sh);
    int ok = 0;
    gl->GetShaderiv(sh, 0x8B81 /* GL_COMPILE_STATUS */, &ok);
    if (!ok) { char log[1024]; gl->GetShaderInfoLog(sh, sizeof(log), NULL, log); printf("    %s\n", log); }
    return sh;
}

// Program of a vertex stage (the instanced one, or the batch-record one), capturing its outputs,
// in the context's dialect (as the header's loader writes it). ES 3.0 links no program without a
// fragment stage: an empty one.
static GLu tfStageProgram(TfGl *gl, const char *defines, const char *const *const *stage)
{
    bool es = (rbl__glsl() == 300);
    char prologue[256];
    rbl__stagePrologue(es? 300 : 330, true, defines, prologue, sizeof(prologue));
    char *vs = rbl__joinStage(prologue, stage);
    GLu vsh = tfShader(gl, 0x8B31 /* GL_VERTEX_SHADER */, vs);
    RBL_FREE(vs);
    GLu fsh = tfShader(gl, 0x8B30 /* GL_FRAGMENT_SHADER */, es? "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(0.0); }\n"
                                                               : "#version 330\nout vec4 c;\nvoid main() { c = vec4(0.0); }\n");
    GLu prog = gl->CreateProgram();
    gl->AttachShader(prog, vsh);
    gl->AttachShader(prog, fsh);
    const char *varyings[] = { "fragPosition", "fragTexCoord", "fragNormal", "fragTangent" };
    gl->TransformFeedbackVaryings(prog, 4, varyings, 0x8C8C /* GL_INTERLEAVED_ATTRIBS */);
    gl->LinkProgram(prog);
    int ok = 0;
    gl->GetProgramiv(prog, 0x8B82 /* GL_LINK_STATUS */, &ok);
    gl->DeleteShader(vsh);
    gl->DeleteShader(fsh);
    if (!ok) { gl->DeleteProgram(prog); return 0; }
    return prog;
}

static GLu tfProgram(TfGl *gl) { return tfStageProgram(gl, "#define RBL_LIGHTS 1\n", rbl__pass_lit_instanced_vs); }
static GLu tfRecordProgram(TfGl *gl) { return tfStageProgram(gl, "#define RBL_LIGHTS 1\n#define RBL_BATCH_RECORD\n", rbl__pass_lit_instanced_vs); }

// Shadow-pass fields of the captured frame (zero: a colour pass); the shadow tests set them
static Vector4 tfLight;
static float tfMinCastSin;
static int tfFacingFlags;           // added to the facing code: 8 light-facing casters (AXIS tilts turn the front face)
static float tfOrthographic;        // 1: the frame of an orthographic camera (set by the orthographic tests)

// A capture's set-up: a scratch target (a complete framebuffer must be bound even with
// rasterisation discarded: surfaceless has none), prog with identity matrices, and a feedback buffer
// of bytes bound at index 0
typedef struct { RenderTexture2D scratch; GLu buffer; size_t bytes; } TfRun;

static TfRun tfBegin(TfGl *gl, GLu prog, size_t bytes)
{
    TfRun run;
    run.scratch = LoadRenderTexture(4, 4);
    run.bytes = bytes;
    run.buffer = 0;
    BeginTextureMode(run.scratch);
    rlEnableShader(prog);
    rlSetUniformMatrix(rlGetLocationUniform(prog, "mvp"), rbl__identity());
    rlSetUniformMatrix(rlGetLocationUniform(prog, "matModel"), rbl__identity());
    rlSetUniformMatrix(rlGetLocationUniform(prog, "matNormal"), rbl__identity());
    gl->GenBuffers(1, &run.buffer);
    gl->BindBuffer(0x8C8E /* GL_TRANSFORM_FEEDBACK_BUFFER */, run.buffer);
    gl->BufferData(0x8C8E, (ptrdiff_t)bytes, NULL, 0x88E5 /* GL_STATIC_READ */);
    gl->BindBufferBase(0x8C8E, 0, run.buffer);
    return run;
}

// Draws count vertices of each of n instances from the bound vertex array into the feedback buffer,
// then reads it back (NaN where it cannot be mapped; NULL out of memory)
static float *tfEnd(TfGl *gl, TfRun *run, int count, int n)
{
    gl->Enable(0x8C89 /* GL_RASTERIZER_DISCARD */);
    gl->BeginTransformFeedback(0x0004 /* GL_TRIANGLES */);
    rlDrawVertexArrayInstanced(0, count, n);
    gl->EndTransformFeedback();
    gl->Disable(0x8C89);
    rlDisableVertexArray();
    rlDisableShader();
    EndTextureMode();
    UnloadRenderTexture(run->scratch);
    float *out = (float *)malloc(run->bytes);
    // Mapped, not glGetBufferSubData: ES 3.0 has no buffer read-back call
    const void *mapped = gl->MapBufferRange(0x8C8E, 0, (ptrdiff_t)run->bytes, 0x0001 /* GL_MAP_READ_BIT */);
    if ((mapped != NULL) && (out != NULL)) memcpy(out, mapped, run->bytes);
    else if (out != NULL) for (size_t i = 0; i < run->bytes/sizeof(float); i++) out[i] = NAN;
    if (mapped != NULL) gl->UnmapBuffer(0x8C8E);
    gl->DeleteBuffers(1, &run->buffer);
    return out;
}

// Runs the instanced vertex stage over instances and returns 6 captured vertices per instance
static float *tfCapture(TfGl *gl, GLu prog, RblInstanceBuffer *buf, Camera3D cam, RblInstancedDesc d, int texW, int texH, const RblInstance *in, int n)
{
    RblCameraFrame view = RblGetCameraFrame(cam);
    TfRun run = tfBegin(gl, prog, (size_t)n*6*TF_FLOATS*sizeof(float));
    const float frame[28] = {
        view.eye.x, view.eye.y, view.eye.z, (float)(d.facing + tfFacingFlags), view.right.x, view.right.y, view.right.z, d.roundness,
        view.up.x, view.up.y, view.up.z, (float)texW, view.back.x, view.back.y, view.back.z, (float)texH,
        d.up.x, d.up.y, d.up.z, tfMinCastSin, d.axis.x, d.axis.y, d.axis.z, tfOrthographic, tfLight.x, tfLight.y, tfLight.z, tfLight.w };
    rlSetUniform(rlGetLocationUniform(prog, "rblInstancing"), frame, SHADER_UNIFORM_VEC4, 7);
    rlEnableVertexArray(buf->state->vaoId);
    rlUpdateVertexBuffer(buf->state->vboId, in, n*(int)sizeof(RblInstance), 0);
    return tfEnd(gl, &run, 6, n);
}

// Runs the batch-record vertex stage (tfRecordProgram) over the first n records a batch uploaded at
// its last RblEndBatch, with the frame its first run drew with (rbl__recordFrame: call it in the pass
// the batch drew in), and returns 6 captured vertices per record (corners 0, 1, 2, 0, 2, 3)
static float *tfCaptureRecords(TfGl *gl, GLu prog, const rbl__BatchState *st, int n)
{
    float frame[32];
    rbl__recordFrame(st, 0, frame);
    TfRun run = tfBegin(gl, prog, (size_t)n*6*TF_FLOATS*sizeof(float));
    rlSetUniform(rlGetLocationUniform(prog, "rblInstancing"), frame, SHADER_UNIFORM_VEC4, 7);
    rlEnableVertexArray(st->recordVaoId);
    rbl__setRecordLayout(st, 0);
    return tfEnd(gl, &run, 6, n);
}

#endif // RBL_TESTS_TF_CAPTURE_H
