// A small GPU-skinned raylib Model built in code (no model file needed) and its CPU reference:
// a square column along +Z (24 segments), three bones in a chain at z = 0, 0.8, 1.6, and a plate
// beside it whose vertices have all-zero weights. Two keyframes: 0 = the bind pose, 1 = base moved
// and twisted, upper bones bent about Y. Weights: the lowest part has near-degenerate weights
// (1 - 3e-6 on bone 0, 1e-6 on each of the others), joints blend linearly between two bones.
// skinReference skins the bind mesh in double precision from the keyframe Transforms, from the
// published linear-blend formula (p' = sum w M p, n' = sum w M^-T n), independently of raymath.
// Used by tests/test_skinning.c, tests/test_contracts.c and tests/bench/bench_lighting.c.
#ifndef RBL_TEST_SKIN_RIG_H
#define RBL_TEST_SKIN_RIG_H

#include "raylib.h"
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>         // abs
#include "harness.h"        // rtPixel
#include <stdio.h>
#include <string.h>

#define SKIN_BONES 3
#define SKIN_SEGMENTS 24
#define SKIN_HEIGHT 2.4f
#define SKIN_HALF 0.25f

typedef struct SkinRig {
    Model model;
    ModelAnimation anim;        // 2 keyframes
} SkinRig;

// Unit quaternion of angle degrees about a unit axis, in double
static inline void skinQuat(double ax, double ay, double az, double degrees, double q[4])
{
    double h = degrees*3.14159265358979323846/360.0;
    q[0] = ax*sin(h); q[1] = ay*sin(h); q[2] = az*sin(h); q[3] = cos(h);
}
static inline void skinQuatMul(const double a[4], const double b[4], double out[4])     // a then applied after b: a*b
{
    double r[4] = { a[3]*b[0] + a[0]*b[3] + a[1]*b[2] - a[2]*b[1], a[3]*b[1] - a[0]*b[2] + a[1]*b[3] + a[2]*b[0],
                    a[3]*b[2] + a[0]*b[1] - a[1]*b[0] + a[2]*b[3], a[3]*b[3] - a[0]*b[0] - a[1]*b[1] - a[2]*b[2] };
    memcpy(out, r, sizeof(r));
}
// Rotation matrix of quaternion (x, y, z, w), row-major r[row][col] (the standard formula, not renormalised)
static inline void skinQuatMatrix(Quaternion q, double r[3][3])
{
    double x = q.x, y = q.y, z = q.z, w = q.w;
    r[0][0] = 1 - 2*(y*y + z*z); r[0][1] = 2*(x*y - z*w);     r[0][2] = 2*(x*z + y*w);
    r[1][0] = 2*(x*y + z*w);     r[1][1] = 1 - 2*(x*x + z*z); r[1][2] = 2*(y*z - x*w);
    r[2][0] = 2*(x*z - y*w);     r[2][1] = 2*(y*z + x*w);     r[2][2] = 1 - 2*(x*x + y*y);
}
static inline void skinInvert3(double m[3][3], double inv[3][3])
{
    double c00 = m[1][1]*m[2][2] - m[1][2]*m[2][1], c01 = m[1][2]*m[2][0] - m[1][0]*m[2][2], c02 = m[1][0]*m[2][1] - m[1][1]*m[2][0];
    double det = m[0][0]*c00 + m[0][1]*c01 + m[0][2]*c02;
    inv[0][0] = c00/det; inv[0][1] = (m[0][2]*m[2][1] - m[0][1]*m[2][2])/det; inv[0][2] = (m[0][1]*m[1][2] - m[0][2]*m[1][1])/det;
    inv[1][0] = c01/det; inv[1][1] = (m[0][0]*m[2][2] - m[0][2]*m[2][0])/det; inv[1][2] = (m[0][2]*m[1][0] - m[0][0]*m[1][2])/det;
    inv[2][0] = c02/det; inv[2][1] = (m[0][1]*m[2][0] - m[0][0]*m[2][1])/det; inv[2][2] = (m[0][0]*m[1][1] - m[0][1]*m[1][0])/det;
}

// Bone b's skinning transform in double: p -> L p + o, L = Rc Sc Sb^-1 Rb^-1, o = tc - L tb
static inline void skinBoneTransform(Transform bind, Transform pose, double L[3][3], double o[3])
{
    double rb[3][3], rc[3][3], rbi[3][3];
    skinQuatMatrix(bind.rotation, rb);
    skinQuatMatrix(pose.rotation, rc);
    skinInvert3(rb, rbi);
    double sb[3] = { bind.scale.x, bind.scale.y, bind.scale.z }, sc[3] = { pose.scale.x, pose.scale.y, pose.scale.z };
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
        {
            double s = 0.0;
            for (int k = 0; k < 3; k++) s += rc[i][k]*sc[k]/sb[k]*rbi[k][j];
            L[i][j] = s;
        }
    double tb[3] = { bind.translation.x, bind.translation.y, bind.translation.z };
    o[0] = pose.translation.x; o[1] = pose.translation.y; o[2] = pose.translation.z;
    for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) o[i] -= L[i][j]*tb[j];
}

// Skins mesh (bind pose: vertices, normals, tangents) with the pose in double; writes floats (tangents may be NULL).
// A vertex whose weights are all zero keeps its bind pose (the header's documented rule).
static inline void skinReference(const Mesh *mesh, const Transform *bind, const Transform *pose, int boneCount, float *outPos, float *outNormal, float *outTangent)
{
    double L[256][3][3], o[256][3], N[256][3][3];
    for (int b = 0; b < boneCount; b++)
    {
        skinBoneTransform(bind[b], pose[b], L[b], o[b]);
        double inv[3][3];
        skinInvert3(L[b], inv);
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) N[b][i][j] = inv[j][i];      // inverse transpose
    }
    for (int v = 0; v < mesh->vertexCount; v++)
    {
        const float *p = &mesh->vertices[v*3], *n = &mesh->normals[v*3];
        const float *t = (mesh->tangents != NULL)? &mesh->tangents[v*4] : NULL;
        double sp[3] = { 0, 0, 0 }, sn[3] = { 0, 0, 0 }, st[3] = { 0, 0, 0 }, total = 0.0;
        for (int k = 0; k < 4; k++)
        {
            double w = mesh->boneWeights[v*4 + k];
            int b = mesh->boneIndices[v*4 + k];
            if (w == 0.0) continue;
            total += fabs(w);
            for (int i = 0; i < 3; i++)
            {
                sp[i] += w*(L[b][i][0]*p[0] + L[b][i][1]*p[1] + L[b][i][2]*p[2] + o[b][i]);
                sn[i] += w*(N[b][i][0]*n[0] + N[b][i][1]*n[1] + N[b][i][2]*n[2]);
                if (t != NULL) st[i] += w*(L[b][i][0]*t[0] + L[b][i][1]*t[1] + L[b][i][2]*t[2]);
            }
        }
        for (int i = 0; i < 3; i++)
        {
            outPos[v*3 + i] = (float)((total > 0.0)? sp[i] : p[i]);
            outNormal[v*3 + i] = (float)((total > 0.0)? sn[i] : n[i]);
            if ((t != NULL) && (outTangent != NULL)) outTangent[v*4 + i] = (float)((total > 0.0)? st[i] : t[i]);
        }
        if ((t != NULL) && (outTangent != NULL)) outTangent[v*4 + 3] = t[3];
    }
}

// Bone weights of a column vertex at height z (see the top of the file)
static inline void skinColumnWeights(float z, unsigned char ids[4], float w[4])
{
    memset(ids, 0, 4); memset(w, 0, 4*sizeof(float));
    if (z < 0.6f) { ids[0] = 0; ids[1] = 1; ids[2] = 2; ids[3] = 1; w[0] = 1.0f - 3e-6f; w[1] = w[2] = w[3] = 1e-6f; }
    else if (z < 1.0f) { float t = (z - 0.6f)/0.4f; ids[0] = 0; ids[1] = 1; w[0] = 1.0f - t; w[1] = t; }
    else if (z < 1.4f) { ids[0] = 1; w[0] = 1.0f; }
    else if (z < 1.8f) { float t = (z - 1.4f)/0.4f; ids[0] = 1; ids[1] = 2; w[0] = 1.0f - t; w[1] = t; }
    else { ids[0] = 2; w[0] = 1.0f; }
}

// The bind mesh (CPU arrays only; upload with UploadMesh): segments per side (<= 8000), with or without the plate
static inline Mesh skinMesh(int segments, bool plateToo)
{
    const int sideVerts = (segments + 1)*2;
    Mesh m;
    memset(&m, 0, sizeof(m));
    m.vertexCount = 4*sideVerts + 4 + (plateToo? 4 : 0);
    m.triangleCount = 4*segments*2 + 2 + (plateToo? 2 : 0);
    m.vertices = (float *)MemAlloc((unsigned int)(m.vertexCount*3*sizeof(float)));
    m.normals = (float *)MemAlloc((unsigned int)(m.vertexCount*3*sizeof(float)));
    m.texcoords = (float *)MemAlloc((unsigned int)(m.vertexCount*2*sizeof(float)));
    m.tangents = (float *)MemAlloc((unsigned int)(m.vertexCount*4*sizeof(float)));
    m.boneIndices = (unsigned char *)MemAlloc((unsigned int)(m.vertexCount*4));
    m.boneWeights = (float *)MemAlloc((unsigned int)(m.vertexCount*4*sizeof(float)));
    m.indices = (unsigned short *)MemAlloc((unsigned int)(m.triangleCount*3*sizeof(unsigned short)));
    m.boneCount = SKIN_BONES;
    int v = 0, t = 0;
    // Sides: outward normal n, tangent along the face (right-handed with +Z up)
    static const float side[4][4] = { { 0, -1, 1, 0 }, { 1, 0, 0, 1 }, { 0, 1, -1, 0 }, { -1, 0, 0, -1 } };   // nx, ny, tx, ty
    for (int s = 0; s < 4; s++)
    {
        int base = v;
        float nx = side[s][0], ny = side[s][1], tx = side[s][2], ty = side[s][3];
        for (int i = 0; i <= segments; i++)
        {
            float z = SKIN_HEIGHT*(float)i/(float)segments;
            for (int e = 0; e < 2; e++)
            {
                float u = (e == 0)? -1.0f : 1.0f;
                float *p = &m.vertices[v*3];
                p[0] = nx*SKIN_HALF + tx*u*SKIN_HALF; p[1] = ny*SKIN_HALF + ty*u*SKIN_HALF; p[2] = z;
                m.normals[v*3] = nx; m.normals[v*3 + 1] = ny; m.normals[v*3 + 2] = 0.0f;
                m.tangents[v*4] = tx; m.tangents[v*4 + 1] = ty; m.tangents[v*4 + 2] = 0.0f; m.tangents[v*4 + 3] = 1.0f;
                m.texcoords[v*2] = (float)e; m.texcoords[v*2 + 1] = 1.0f - (float)i/(float)segments;
                skinColumnWeights(z, &m.boneIndices[v*4], &m.boneWeights[v*4]);
                v++;
            }
        }
        for (int i = 0; i < segments; i++)
        {
            unsigned short a = (unsigned short)(base + i*2), b = (unsigned short)(a + 1), c = (unsigned short)(a + 3), d = (unsigned short)(a + 2);
            unsigned short tri[6] = { a, b, c, a, c, d };
            memcpy(&m.indices[t*3], tri, sizeof(tri));
            t += 2;
        }
    }
    // Top cap on bone 2, then the zero-weight plate beside the column (facing -Y)
    static const float cap[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    static const float plate[4][3] = { { 0.8f, 0.0f, 0.0f }, { 1.4f, 0.0f, 0.0f }, { 1.4f, 0.0f, 0.8f }, { 0.8f, 0.0f, 0.8f } };
    for (int q = 0; q < (plateToo? 2 : 1); q++)
    {
        int base = v;
        for (int i = 0; i < 4; i++)
        {
            float *p = &m.vertices[v*3];
            if (q == 0) { p[0] = cap[i][0]*SKIN_HALF; p[1] = cap[i][1]*SKIN_HALF; p[2] = SKIN_HEIGHT; }
            else { p[0] = plate[i][0]; p[1] = plate[i][1]; p[2] = plate[i][2]; }
            m.normals[v*3] = 0.0f; m.normals[v*3 + 1] = (q == 0)? 0.0f : -1.0f; m.normals[v*3 + 2] = (q == 0)? 1.0f : 0.0f;
            m.tangents[v*4] = 1.0f; m.tangents[v*4 + 1] = 0.0f; m.tangents[v*4 + 2] = 0.0f; m.tangents[v*4 + 3] = 1.0f;
            m.texcoords[v*2] = (i == 1 || i == 2)? 1.0f : 0.0f; m.texcoords[v*2 + 1] = (i >= 2)? 0.0f : 1.0f;
            if (q == 0) { float z = SKIN_HEIGHT; skinColumnWeights(z, &m.boneIndices[v*4], &m.boneWeights[v*4]); }
            else { memset(&m.boneIndices[v*4], 0, 4); memset(&m.boneWeights[v*4], 0, 4*sizeof(float)); }
            v++;
        }
        unsigned short tri[6] = { (unsigned short)base, (unsigned short)(base + 1), (unsigned short)(base + 2), (unsigned short)base, (unsigned short)(base + 2), (unsigned short)(base + 3) };
        memcpy(&m.indices[t*3], tri, sizeof(tri));
        t += 2;
    }
    return m;
}

// The Model around skinMesh() (uploaded), its skeleton and a 2-keyframe animation. cpuSkinned:
// raylib's CPU skinning instead (animVertices/animNormals allocated: UpdateModelAnimation skins
// them on the CPU and re-uploads the vertex buffers; drawn by an unskinned program)
static inline SkinRig skinRigLoadEx(int segments, bool plateToo, bool cpuSkinned)
{
    SkinRig r;
    memset(&r, 0, sizeof(r));
    Mesh mesh = skinMesh(segments, plateToo);
    if (cpuSkinned)
    {
        mesh.animVertices = (float *)MemAlloc((unsigned int)(mesh.vertexCount*3*sizeof(float)));
        mesh.animNormals = (float *)MemAlloc((unsigned int)(mesh.vertexCount*3*sizeof(float)));
        memcpy(mesh.animVertices, mesh.vertices, (size_t)mesh.vertexCount*3*sizeof(float));
        memcpy(mesh.animNormals, mesh.normals, (size_t)mesh.vertexCount*3*sizeof(float));
    }
    UploadMesh(&mesh, cpuSkinned);
    r.model = LoadModelFromMesh(mesh);
    ModelSkeleton *sk = &r.model.skeleton;
    sk->boneCount = SKIN_BONES;
    sk->bones = (BoneInfo *)MemAlloc(SKIN_BONES*sizeof(BoneInfo));
    sk->bindPose = (Transform *)MemAlloc(SKIN_BONES*sizeof(Transform));
    r.model.currentPose = (Transform *)MemAlloc(SKIN_BONES*sizeof(Transform));
    r.model.boneMatrices = (Matrix *)MemAlloc(SKIN_BONES*sizeof(Matrix));
    r.anim.boneCount = SKIN_BONES;
    r.anim.keyframeCount = 2;
    r.anim.keyframePoses = (ModelAnimPose *)MemAlloc(2*sizeof(ModelAnimPose));
    for (int f = 0; f < 2; f++) r.anim.keyframePoses[f] = (Transform *)MemAlloc(SKIN_BONES*sizeof(Transform));
    double q0[4], qy[4], q1[4], q2[4];
    skinQuat(0, 0, 1, 15.0, q0);                // base twisted about Z
    skinQuat(0, 1, 0, 25.0, qy);
    skinQuatMul(q0, qy, q1);                    // each upper bone bends 25 degrees more about its Y
    skinQuatMul(q1, qy, q2);
    const double *qs[3] = { q0, q1, q2 };
    double t[3][3] = { { 0.15, 0.0, 0.0 } };
    for (int b = 1; b < 3; b++)             // joint b = joint b-1 + R(b-1) (0, 0, 0.8)
    {
        Quaternion pq = { (float)qs[b - 1][0], (float)qs[b - 1][1], (float)qs[b - 1][2], (float)qs[b - 1][3] };
        double rm[3][3];
        skinQuatMatrix(pq, rm);
        for (int i = 0; i < 3; i++) t[b][i] = t[b - 1][i] + rm[i][2]*0.8;
    }
    for (int b = 0; b < SKIN_BONES; b++)
    {
        snprintf(sk->bones[b].name, sizeof(sk->bones[b].name), "bone%d", b);
        sk->bones[b].parent = b - 1;
        Transform bind = { { 0.0f, 0.0f, 0.8f*(float)b }, { 0.0f, 0.0f, 0.0f, 1.0f }, { 1.0f, 1.0f, 1.0f } };
        sk->bindPose[b] = bind;
        r.model.currentPose[b] = bind;
        r.model.boneMatrices[b] = MatrixIdentity();
        r.anim.keyframePoses[0][b] = bind;
        Transform bent = { { (float)t[b][0], (float)t[b][1], (float)t[b][2] }, { (float)qs[b][0], (float)qs[b][1], (float)qs[b][2], (float)qs[b][3] }, { 1.0f, 1.0f, 1.0f } };
        r.anim.keyframePoses[1][b] = bent;
    }
    return r;
}

static inline SkinRig skinRigLoad(void) { return skinRigLoadEx(SKIN_SEGMENTS, true, false); }

static inline void skinRigUnload(SkinRig *r)
{
    // raylib 6.0's UnloadModel frees neither currentPose nor boneMatrices
    MemFree(r->model.currentPose); r->model.currentPose = NULL;
    MemFree(r->model.boneMatrices); r->model.boneMatrices = NULL;
    UnloadModel(r->model);
    for (int f = 0; f < r->anim.keyframeCount; f++) MemFree(r->anim.keyframePoses[f]);
    MemFree(r->anim.keyframePoses);
    memset(r, 0, sizeof(*r));
}

// A Model of the CPU-skinned mesh at keyframe `frame` (no bone data: drawn by an unskinned program)
static inline Model skinCpuModel(const SkinRig *r, int frame)
{
    const Mesh *src = &r->model.meshes[0];
    Mesh m;
    memset(&m, 0, sizeof(m));
    m.vertexCount = src->vertexCount;
    m.triangleCount = src->triangleCount;
    m.vertices = (float *)MemAlloc((unsigned int)(m.vertexCount*3*sizeof(float)));
    m.normals = (float *)MemAlloc((unsigned int)(m.vertexCount*3*sizeof(float)));
    m.tangents = (float *)MemAlloc((unsigned int)(m.vertexCount*4*sizeof(float)));
    m.texcoords = (float *)MemAlloc((unsigned int)(m.vertexCount*2*sizeof(float)));
    m.indices = (unsigned short *)MemAlloc((unsigned int)(m.triangleCount*3*sizeof(unsigned short)));
    memcpy(m.texcoords, src->texcoords, (size_t)m.vertexCount*2*sizeof(float));
    memcpy(m.indices, src->indices, (size_t)m.triangleCount*3*sizeof(unsigned short));
    skinReference(src, r->model.skeleton.bindPose, r->anim.keyframePoses[frame], SKIN_BONES, m.vertices, m.normals, m.tangents);
    UploadMesh(&m, false);
    return LoadModelFromMesh(m);
}

// An edge pixel: its 3x3 neighbourhood in a or b holds background, or a colour step above 8/255 (a
// silhouette or a crease, where a position rounded differently moves which triangle covers it)
static inline bool skEdge(Image img, int x, int y)
{
    Color c = rtPixel(img, x, y);
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
        {
            int u = x + dx, v = y + dy;
            if ((u < 0) || (v < 0) || (u >= img.width) || (v >= img.height)) return true;
            Color n = rtPixel(img, u, v);
            if ((n.a != c.a) || (abs(n.r - c.r) > 8) || (abs(n.g - c.g) > 8) || (abs(n.b - c.b) > 8)) return true;
        }
    return false;
}

#endif
