/**********************************************************************************************
*
*   rbillboard_lit v0.5 - Lit billboards for raylib: normals, tangents, materials, lights and shadows
*
*   DESCRIPTION:
*       A raylib billboard (DrawBillboardPro) is two triangles with a colour and texture coordinates:
*       no normal, no tangent, no material, so no shader can light it. This header emits billboard
*       quads carrying a normal and a tangent (xyz + handedness) in every facing mode, through its own
*       vertex buffers (rlgl's batch has no tangent attribute), and compiles lit programs with raylib's
*       attribute and uniform names, so one program in a Material lights billboards and Models alike.
*       On top: packed material maps, forward and deferred lighting, and shadow maps in which a
*       sprite's cut-out casts its own shape.
*
*   CONTENTS:
*       This block: INTEGRATION (nine stages, each building on the last), then reference: MATERIAL
*       VALUES, OWNERSHIP, FACING MODES, DEGENERATE FRAMES, CONVENTIONS, DEVIATIONS FROM raylib,
*       LIGHTING, DEFERRED, SHADOWS, THIN SPRITES, MATERIAL LAYOUT, SPRITE SHEETS, LIMITATIONS, CONFIGURATION, VERSIONS HISTORY,
*       DEPENDENCIES, LICENSE.
*       The file, in order (each section's banner ends with its tag: search ">>geometry" to jump there;
*       make test checks this list against the banners):
*         >>config      Defines and Macros: configuration defaults (CONFIGURATION), RBL_ZERO
*         >>types       public types, in the order the stages use them
*         >>api         public functions, one group per stage (README's API index is made from them)
*         >>private     private types: uniform table, registry entry, packed scene, the header's state
*         >>shaders     generated data: the shaders/ sources as strings, includes resolved (make shaders; a
*                       test fails if they differ; skip it when reading the code)
*         >>vec         small vector helpers
*         >>geometry    camera frame, facing frames, quad corners (CPU)
*         >>batch       batched and immediate paths: vertex buffers, material runs, sorting, draws
*         >>instanced   instanced path: per-instance data, quads expanded in the vertex shader
*         >>maps        material maps: texel access, sRGB and mips, packing, authoring help (CPU)
*         >>lit         lit shader variants: #defines before the embedded sources, compilation
*         >>registry    the program registry: one entry per compiled program, shared by equal keys
*         >>programs    lit programs and per-draw material values (Shader handles, Material -> uniforms)
*         >>scene       RblSetScene: validate, pack, upload to every live program; scene depth
*         >>deferred    deferred G-buffer: geometry pass, light passes, resolve
*         >>shadows     shadow maps: light cameras, caster passes, caster identities
*         >>atlas       sprite-sheet atlases and animation: JSON, sheet files, libGDX, slices, a page's
*                       textures, the player (RBL_NO_ATLAS leaves it out)
*         >>sprites     resident sprite buffers: the frame table, range updates, chunk culling, the draw with
*                       the instanced program's sprite variant (RBL_NO_ATLAS leaves it out)
*
*   INTEGRATION:
*       1. One lit billboard. `#define RBILLBOARD_LIT_IMPLEMENTATION` before the #include in exactly
*          one .c file. The lit program is a Shader for a Material, whose maps also carry the values
*          (MATERIAL VALUES); lights, ambient, fog and exposure are one RblScene set each frame.
*          Structs start as RBL_ZERO and get their fields assigned (valid C99 and C++11 alike).
*            Material mat = LoadMaterialDefault();
*            RblLitShaderDesc desc = RBL_ZERO;     // zero: 4 point lights, Lambert
*            mat.shader = RblLoadLitShader(desc);
*            mat.maps[MATERIAL_MAP_ALBEDO].texture = LoadTexture("sprite.png");
*            RblLight light = RBL_ZERO;            // a point light
*            light.position = CLITERAL(Vector3){ 2, 3, 2 }; light.color = WHITE; light.intensity = 20; light.range = 15;
*            RblScene scene = RBL_ZERO;
*            scene.lights = &light; scene.lightCount = 1; scene.ambient = DARKGRAY;
*            RblSetScene(&scene);                  // each frame; false: rejected, previous kept
*            RblBillboard sprite = RBL_ZERO;
*            sprite.position = p; sprite.size = CLITERAL(Vector2){ 1, 2 };
*            RblDrawBillboard(camera, mat, sprite); // in BeginMode3D
*          At exit: UnloadMaterial(mat), RblClose(), CloseWindow() (see OWNERSHIP).
*       2. Many billboards: consecutive billboards with the same Material (shader, maps array,
*          params) form one run; RblEndBatch uploads once and draws once per run (and reads the
*          maps' values then).
*            RblBatch batch = RblLoadBatch(0);     // RBL_BATCH_DEFAULT_CAPACITY; grows (log line)
*            RblBeginBatch(&batch, camera);        // inside BeginMode3D
*            for (int i = 0; i < n; i++) RblBatchAdd(&batch, mat, &billboards[i]);   // false: skipped
*            RblEndBatch(&batch);
*          An array of one material goes in one call, the same as the loop at less cost a billboard:
*            RblBatchAddMany(&batch, mat, billboards, n);   // returns how many were not skipped
*       3. Packed maps: albedo + one RGBA8 material texture (+ emissive); the reported layout selects
*          the program variant, so absent maps are never sampled (MATERIAL LAYOUT).
*            RblMaterialSource src = RBL_ZERO;
*            src.albedo = albedoImage; src.normal = normalImage; src.mipmaps = true;
*            RblPackedMaterial packed = RBL_ZERO;
*            if (RblPackMaterial(&src, &packed) && RblLoadPackedTextures(&packed, &mat))
*                desc.material = packed.layout;    // then mat.shader = RblLoadLitShader(desc)
*            RblUnloadPackedMaterial(&packed);     // the CPU Images; the textures stay in mat
*       4. Instanced: 56 bytes per billboard, quads expanded in the vertex shader by its own variant;
*          facing, up, axis and roundness are shared by one draw.
*            desc.instanced = true; instMat.shader = RblLoadLitShader(desc);
*            RblInstanceBuffer ib = RblLoadInstanceBuffer(0);
*            RblInstancedDesc idesc = RBL_ZERO;
*            idesc.facing = RBL_FACING_AXIS;
*            RblDrawInstanced(&ib, camera, instMat, idesc, instances, count);   // inside BeginMode3D
*       5. raylib Models: a lit program in model.materials[i].shader (GenMeshTangents for normal maps).
*          RblSetScene uploads the scene to every live lit program (later ones get it at load), so even
*          raylib's DrawModel is lit; the Material's values need these (they then call DrawMesh):
*            RblDrawModel(model, position, scale, tint);     // DrawModel's arguments
*            RblDrawMesh(mesh, material, transform);
*          GPU-skinned Models (raylib built with SUPPORT_GPU_SKINNING): desc.skinning = true, then
*          UpdateModelAnimation and RblDrawModel, which uploads model.boneMatrices; shadow passes skin
*          such a Model's caster by its own data. Sum as raylib's CPU skinning (normals by the inverse
*          transpose); a vertex with all four weights zero keeps its bind pose. Refused with a log line:
*          boneMatrices NULL, skeleton.boneCount outside 1..RBL_MAX_BONES, NaN/huge bones, meshes
*          without GPU bone data, RblDrawMesh and billboards with a skinned program.
*       6. Shadows (directional, spot and point lights): before BeginMode3D, draw the casters with the same
*          calls and materials as the colour pass, then list the maps in the scene.
*            RblShadowMap sun = RblLoadShadowMap(shadowDesc);  // receivers: desc.shading.shadowMaps = 1
*            RblShadowFocusFromCamera(camera, aspect, 0.1f, 30.0f, &focus, &radius);
*            scene.shadowMapCount = 0;                         // no map unless its pass ran
*            if (RblBeginShadowMap(&sun, &scene, 0, focus, radius)) {      // scene.lights[0] casts
*                ... batches, RblDrawInstanced, RblDrawBillboard, RblDrawModel ...
*                RblEndShadowMap(&sun);
*                scene.shadowMaps = &sun; scene.shadowMapCount = 1;
*            }
*            RblSetScene(&scene);                  // after the passes: it reads their matrices
*          Point lights (desc.omni) and cascaded suns (desc.cascades) take RblShadowMapPasses(map)
*          passes a frame, each drawing the same casters (cascades: RblFitShadowCascades first):
*            for (int i = 0; i < RblShadowMapPasses(map); i++)
*                if (RblBeginShadowMapPass(&map, &scene, light, i, focus, radius)) { ... RblEndShadowMap(&map); }
*       7. Deferred (hundreds of lights): opaque draws into a G-buffer with geometry-pass variants
*          (desc.deferred = true, the G-buffer's RblShading), lit by the same scene, then resolved.
*            RblGBufferDesc gdesc = RBL_ZERO;      // size 0: follows its target's size
*            gdesc.shading.brdf = RBL_BRDF_GGX;
*            RblGBuffer g = RblLoadGBuffer(gdesc);
*            surface.shading = gdesc.shading; surface.deferred = true;   // its materials' programs
*            RblSetScene(&scene);                  // each frame, before BeginDrawing():
*            if (RblBeginGBuffer(&g, camera)) {    // false: draw this frame forward
*                ... billboard paths and RblDrawModel with deferred materials ...
*                RblEndGBuffer(&g);
*                RblDrawDeferredLights(&g);        // the scene's ambient and lights
*            }
*            // inside BeginDrawing/BeginTextureMode: RblResolveGBuffer(&g), then BeginMode3D and
*            // forward draws (transparent billboards), depth-tested against the G-buffer's depth
*          Forward fallback: without MRT, float targets or a depth texture, or if a pass fails to
*          compile, the G-buffer is invalid (logged) and RblBeginGBuffer returns false: draw as in 1-6.
*       8. Sprite sheets: an atlas file (TexturePacker, Aseprite, libGDX; SPRITE SHEETS) gives frames,
*          tags and pivots; a player advances a tag; a frame sets a billboard or an instance.
*            RblAtlas atlas = RblLoadAtlas("hero.json");
*            RblLoadAtlasTextures(&atlas, 0, NULL, &mat, &desc.material);   // before RblLoadLitShader
*            RblSpritePlayer walk = RblPlaySprite(&atlas, RblAtlasFindTag(&atlas, "walk"), 0);
*            RblUpdateSprite(&walk, &atlas, GetFrameTime());                 // each frame
*            RblAtlasBillboard(&atlas, walk.frame, 1.0f/32.0f, &sprite);     // 32 pixels a unit
*          Resident sprites (RblSpriteBuffer; stage 4's instanced programs): 32 bytes a sprite,
*          uploaded once and updated by range; frames, trims, pivots and per-frame times come from
*          the atlas's frame table on the GPU, tags play from one clock (RblSpritePlayer's rules),
*          chunks of 256 the view cannot see are skipped. A draw reads nothing per sprite on the CPU.
*            RblSpriteBuffer sb = RblLoadSpriteBuffer(&atlas, count);
*            sprites[i] = RblMakeSprite(position, worldScale, degrees, frame, WHITE);
*            RblAnimateSprite(&sprites[i], tag, -1, startTime, 1.0f);     // or leave it a frame
*            RblUpdateSprites(&sb, 0, count, sprites);                  // again for ranges that change
*            RblDrawSpriteBuffer(&sb, camera, instMat, idesc, time);    // inside BeginMode3D
*       9. Translucent sprites: a batch (or instanced draw) sorts blended billboards; soft particles
*          (desc.softParticles) fade into the opaque world drawn between two added calls.
*            batch.sort = RBL_SORT_BACK_TO_FRONT;  // or RBL_SORT_HYBRID: solid texels opaque
*            RblBeginSceneDepth();                 // inside BeginDrawing: the opaque world's depth kept
*                ... BeginMode3D, opaque draws, EndMode3D ...
*            RblEndSceneDepth();                   // shown; then the blended draws in BeginMode3D
*
*   MATERIAL VALUES (read from the raylib Material at each header draw; zero means default):
*       maps[MATERIAL_MAP_ALBEDO].color      base colour x texture (raylib's colDiffuse; zero = black)
*       maps[MATERIAL_MAP_SPECULAR].color    Blinn-Phong specular colour (sRGB; zero = white)
*       params[RBL_PARAM_SPECULAR]           Blinn-Phong specular intensity (0 = 0.5; with a specular
*                                            map: its scale, 0 = 1)
*       maps[MATERIAL_MAP_NORMAL].value      Blinn-Phong shininess (0 = 32; raylib's OBJ loader: MTL Ns)
*       maps[MATERIAL_MAP_ROUGHNESS].value   GGX perceptual roughness without a map, 0..1 (0 = 0.5)
*       maps[MATERIAL_MAP_METALNESS].value   GGX metalness 0..1 (raylib's glTF loader fills both)
*       maps[MATERIAL_MAP_EMISSION].color    constant emission (sRGB; zero = none)
*       maps[MATERIAL_MAP_EMISSION].value    scale of the constant and mapped emission (0 = 1)
*       params[RBL_PARAM_ALPHA_CUTOFF]       discard below this alpha, casters too (0 = 0.5; <0 = never)
*       params[RBL_PARAM_TRANSMISSION]       desc.transmission: light let through from behind, 0..1 (0 = none)
*       maps[MATERIAL_MAP_HEIGHT].value      desc.relief: height of height 1, in material texels (0 = 4)
*       raylib's MATERIAL_MAP_SPECULAR is MATERIAL_MAP_METALNESS (one slot): its value is the metalness,
*       so the Blinn-Phong intensity has a params slot of its own. NaN/Inf take the default;
*       shininess clamps to >= 1, roughness and metalness to 0..1, specular and emission to >= 0.
*
*   OWNERSHIP:
*       - RblLoadLitShader returns a raylib Shader that is its own GL program (as LoadShader); copies
*         of it (material.shader) are the same holder: release it once, with RblUnloadLitShader(&shader)
*         (zeroes it) or raylib's UnloadShader/UnloadMaterial. Materials that differ only in values
*         share one Shader; equal descs loaded twice are two programs.
*       - Draws recognise a Material's shader by its (id, locs) pair and ask GL that the program still
*         exists before reading anything else of the Material: a stale copy is refused with one line.
*         Draws use the header's own locations, never a Material's.
*       - Batches, instance buffers, G-buffers and shadow maps carry an id: a copy of an unloaded one
*         is refused even when a newer object took its memory.
*       - Shadow maps and G-buffers hold their programs until RblUnloadShadowMap / RblUnloadGBuffer.
*       - RblClose frees what the header owns (immediate path, scene, registry); lit programs become
*         their holders' plain Shaders. Unload your objects before or after it; after CloseWindow the
*         header makes no GL call (unloads free memory only).
*
*   FACING MODES (RblBillboard.facing, or RblInstancedDesc.facing for an instanced draw):
*       CAMERA_PLANE: parallel to the view plane, as DrawBillboard (optional up, as DrawBillboardPro);
*       CAMERA_POSITION: turns toward the eye; AXIS: turns toward the eye about a locked axis (+Y by
*       default); FIXED: a world orientation (axis = normal, up). Under an orthographic camera the eye
*       is at infinity along the view's back direction (RblCameraFrame.orthographic). roundness bends the corner normals
*       outward (sphere, or cylinder about up with RBL_ROUND_CYLINDER) for volume.
*       Two-sided: a quad seen from behind (FIXED, or CAMERA_PLANE with an up against the view's) is
*       drawn and shaded on the side seen (gl_FrontFacing): the normal flips, the normal map's tangent
*       components stay (the card's mirror image through its plane; a relief reads raised from both
*       sides). Models drawn without culling get the same. A draw showing a quad's back turns culling
*       off for itself and back on after; draws of front faces leave it alone.
*
*   DEGENERATE FRAMES:
*       A frame direction taken from a vector off an axis (camera.up off the view, up off a normal, the
*       eye off a locked axis, the light off an AXIS pivot line) blends continuously into a fixed
*       fallback as the two meet: nothing flips, jumps or goes NaN as a degenerate view is approached.
*       The blend, its bands and each case's fallback: README "Degenerate frames" (tests/degenerate.h
*       computes them in double). An up or axis shorter than 1e-12 counts as zero (the default).
*       NaN/Inf input is skipped with one warning per batch or draw, never written to a buffer;
*       instance values must stay below 2^120 in magnitude (the GPU could overflow).
*
*   CONVENTIONS:
*       - Tangent = world direction of +U; cross(normal, tangent.xyz)*tangent.w = world +V, raylib's
*         GenMeshTangents handedness (so Models and billboards share one program), right under every
*         flip (negative size or source extent) and for frames stored rotated (RBL_FRAME_ROTATED).
*       - Normal maps: OpenGL convention (+X right, +Y up in the image as you see it).
*       - Texture slots are raylib's: MATERIAL_MAP_ALBEDO -> texture0, MATERIAL_MAP_NORMAL (packed
*         material texture, or RGB normal map) -> texture2, MATERIAL_MAP_EMISSION -> texture5.
*       - Every Color is sRGB; lighting runs in linear light. Rotation: degrees, reduced mod 360
*         exactly (CPU and GPU alike, any angle), exact at quadrants.
*
*   DEVIATIONS FROM raylib's DrawBillboardPro (deliberate, tested):
*       - Negative size mirrors the image inside the source rectangle and keeps the quad's footprint
*         and pivot. raylib shifts the source rectangle by the world size (source.x -= size.x), right
*         only when |size| equals the source width in pixels, and negates the pivot (the quad moves).
*       - camera.up parallel to the view: raylib's quad collapses (zero right vector); here: fallback.
*         Near it raylib's float frame is off by ~6e-8/s and not orthonormal; here: exact, blended.
*
*   LIGHTING (shaders/lights.glsl, output.glsl; tests/lighting_reference.h: independent, in double):
*       - Units: a light of sRGB colour c and intensity I delivers irradiance E = linear(c)*I*falloff;
*         radiance = pi*BRDF*E*NdotL with pi folded into the light, so a white Lambert surface lit
*         head-on with E = 1 returns 1 (the scale raylib's lighting examples use).
*       - Falloff: windowed E = I*saturate(1 - (d/range)^4)^2/max(d^2, 1e-4) (range 0 = no window);
*         classic E = I/max(constant + linear*d + quadratic*d^2, 1e-4), times the window if range > 0.
*         Spot: t = saturate((cos a - cos outer)/max(cos inner - cos outer, 1e-4)), weight t*t*(3 - 2t).
*       - Blinn-Phong: albedo + specularColor*intensity*(n + 8)/8*NdotH^n (normalised, pi folded);
*         intensity = the specular map (material B) x the value, or the value alone.
*       - GGX: albedo*(1 - metalness) + pi*D*V*F; D = GGX with alpha = roughness^2, V = Smith
*         height-correlated, F = Schlick with F0 = mix(0.04, albedo, metalness); roughness = the map
*         (material B) or the value. 1 - NdotH^2 is computed as |N x H|^2 (no cancellation).
*       - Ambient (flat, or ground..sky by dot(N, up)*0.5 + 0.5) x occlusion x albedo (GGX: albedo*
*         (1 - metalness) + F0). Occlusion dims ambient light only: direct light is occluded by
*         shadows, and darkening it too would count the same blocker twice.
*       - View: v = normalize(eye - p); orthographic cameras (parallel rays): v = the camera's back
*         direction everywhere. Lit programs tell them apart by matProjection (raylib's DrawMesh sets it
*         with matView), instanced draws by their camera, the G-buffer by RblBeginGBuffer's camera.
*       - Fog distance: |p - eye|; orthographic: along the view axis from the camera's plane.
*       - Order: ambient + direct + emission -> fog -> clamp -> exposure -> tonemap -> sRGB (or gamma).
*       - Clamps (no NaN/Inf from any input the API accepts): perceptual roughness >= 0.045, NdotV >=
*         1e-4, falloff denominator >= 1e-4, zero vectors normalise to a fallback, radiance to [0,
*         65504] (half-float max) before exposure and tonemap and again on linear output.
*       - RblSetScene rejects the whole scene (false, one log line, previous kept) for NaN/Inf, negative
*         intensity, range or coefficients, a zero direction, spot angles outside 0 <= inner <= outer
*         <= 90, an unknown type or falloff. A forward program lights the scene's first maxLights
*         lights of the types it compiled (RblGetLightFeatures: what a set needs); others are left out.
*       - LIGHT GRID (desc.clustered; shaders/light_grid.glsl): a clustered program lights every light
*         of the scene of the types it compiled, in one pass, opaque or blended (RBL_MAX_LIGHTS limits
*         the slots, not the scene). The first clustered upload after RblSetScene (in it, or at the
*         program's load) builds one world-space grid on the CPU: uniform cells about 0.75 of the
*         bounded lights' mean range (at most RBL_LIGHT_GRID_MAX_CELLS; 1.5x smaller, up to 3 times,
*         while a cell would list more than RBL_LIGHT_GRID_CELL_LIGHTS), each listing the lights
*         whose sphere (range) touches it; directional lights, range 0, and ranges over a quarter of the
*         lights' extent are lit everywhere. A fragment evaluates its cell's list: the windowed
*         falloff is zero at the range, so the image is the slots' (same scene, every light in a
*         slot). Two float textures (RGBA32F lights, R32F lists) on units RBL_LIGHT_GRID_TEXTURE_UNIT
*         and the next, read with texelFetch. A cell reached by more lights than it lists keeps the
*         scene's first, the others stay unlit there (one log line, again only after a scene without
*         such a cell).
*         The grid is the world's, not the view's: one build serves every camera, target and shadow
*         pass of the frame; a scene no clustered program reads builds none, and programs without
*         desc.clustered compile and run as before. ES 2 / GL 2.1 (no texelFetch): a clustered desc
*         compiles the maxLights slots (one info line).
*
*   DEFERRED (RblGBuffer; shaders/gbuffer_codec.glsl: the layout, deferred_*.fs.glsl: the passes):
*       RblBeginGBuffer -> opaque draws (material, emission, occlusion) -> RblEndGBuffer ->
*       RblDrawDeferredLights (lights into the accumulation) -> RblResolveGBuffer (the ambient once per
*       pixel, fog, exposure, tonemap, encoding; writes depth). The ambient is the scene's at
*       RblBeginGBuffer: set the scene before the geometry pass.
*       Lighting and material decoding are the forward path's code. Colour targets: 10 bytes per pixel
*       (12 where the G-buffer receives shadows: RT2 keeps each pixel's caster identity). Their layout
*       has one home, the comment opening shaders/gbuffer_codec.glsl (embedded below: search for
*       "G-buffer codec:"); README "Deferred" has the measured errors and limits. Depth is a 32-bit
*       float depth texture under raylib's
*       projection (rlgl's cull distances): rlLoadTextureDepth's texture respecified through
*       rlGetProcAddress("glTexImage2D"), since an orthographic camera's depth is linear over the
*       whole clip range (a 24-bit step is (far - near)/2^24 world units everywhere) and a driver's
*       own format may be sampled at fewer bits; without the entry point the driver's format stays.
*       Not stored: position (view z = n f/(f - d (f - n)) straight from the window depth, free of an
*       inverse projection's cancellation; orthographic z = n + d (f - n)), the view vector (the
*       camera's back direction under an orthographic camera), anything derivable. The depth is raylib's
*       own, so later forward draws test against it; lighting tolerates its far-field error.
*       Lights: directional and range-0 lights in full-screen passes; bounded point/spot lights as one
*       instanced draw of sphere proxies (back faces: right with the eye inside). The windowed falloff
*       is zero at the range, so volumes match the naive full-screen loop (g.naiveFullscreen, RBL_INSTRUMENTS, kept for
*       comparison). Debug views: RblSetGBufferOutput.
*       Thin target (RblGBufferDesc.transmission / .relief; shaders/gbuffer_codec.glsl RT4): one more
*       RGBA8 target, a 5th draw buffer (GL_MAX_DRAW_BUFFERS >= 5; ES 3 and WebGL2 promise 4: there
*       the G-buffer is invalid, logged): the transmission share in 16 bits and one relief bit for each
*       of the scene's first 8 lights, marched by the geometry pass toward each light (it knows them:
*       the scene is set before RblBeginGBuffer) and read per light by the light passes. Where the
*       context has a 5th draw buffer every geometry variant writes RT4 (zero without the features)
*       so no hidden layer's values survive; a G-buffer without the flags has 4 targets and its light
*       passes compile none of it. RblGBufferDesc.shadowTransmittance: the light passes read the
*       maps' transmittance targets (no G-buffer bytes: a lookup at the rebuilt position).
*
*   SHADOWS (RblShadowMap; shaders/shadows.glsl: the lookup, shadow_caster.fs.glsl: the casters):
*       Receivers are variants with desc.shading.shadowMaps > 0 (G-buffer: its desc.shading.shadowMaps) and sample the
*       first that many maps of the scene; a forward program shadows a light only if it has a slot.
*       Each map's kind (one camera, omni, cascades) and format (orthographic or perspective, casters
*       target or depth texture) is compiled into the receiver, not branched on per pixel: a program
*       loads compiled for directional maps; a header draw (and each G-buffer light pass) whose scene
*       gives other kinds draws through the registry's variant for them, compiled on first need (one
*       stall when a scene first binds a new kind) and freed with its program. A program receiving
*       single maps holds no face or cascade code. raylib's own DrawModel of a lit program cannot pick
*       a variant: maps of other kinds than its own are left unsampled there (said in its warning).
*       Light cameras: directional = orthographic over the focus sphere (eye 2r before the centre, depth
*       0..3r: casters up to 2r toward the light), moved in whole texels of a world-fixed grid so edges
*       do not crawl as the focus follows the camera; spot = perspective over the outer cone (<= 80
*       degrees), depth range/1000..range (range 0: out to the focus sphere).
*       Point lights (RblShadowDesc.omni): six cube faces in one target, tiles 3 x 2 (+X -X +Y / -Y +Z
*       -Z; up +Z for the Y faces, else +Y; right = axis x up), each a perspective camera at the light
*       over 90 degrees widened by RBL_SHADOW_MAX_FILTER/2 + 2 guard texels per side, depth as a spot's.
*       The lookup takes the face of the point's major axis from the light and builds that face's
*       transform in the shader: one map slot per light, the same bias, PCF and identities as a spot
*       (a 2D target, not a cube texture: texel fetches with identities, on every dialect). Light-
*       facing casters turn toward the light in all six faces (CAMERA_PLANE cards too), so a card
*       drawn into two faces is the same card; a frame draws the casters six times (six passes).
*       Cascades (RblShadowDesc.cascades 2..4, a directional light; tiles in a row): RblFitShadowCascades
*       splits the camera's near..far by the practical split (lambda x logarithmic + (1 - lambda) x
*       uniform, cascadeLambda 0.75) and fits each cascade the smallest sphere around its slice of the
*       view (from the second on, widened by the previous one's blend band): a pan or turn moves the
*       sphere, never resizes it, and its window moves in whole texels of a world-fixed grid, so
*       edges hold still (tests/test_omni_cascades.c: edges and pixels over a pan and a turn).
*       One light frame and depth range serve all cascades; the receiver takes the first cascade
*       whose far split lies beyond its view depth and, inside the last cascadeBlend (0.1) of its
*       depth range, mixes the next cascade's lookup in linearly. Debug view: RblDrawShadowCascades.
*       Casters: inside a pass every header draw swaps in a caster program keeping the material's
*       albedo map, colDiffuse, tint and alpha cutoff (a cut-out casts a cut-out); culling is off.
*       Billboards never shadow themselves: each caster writes its identity with its distance into
*       the map's casters target (RGBA8: rg a 16-bit distance code, ba a 16-bit identity; Models 0), and
*       a billboard receiver ignores every texel holding its own identity, in every PCF fetch. The
*       identity mixes the float bits of the billboard's pivot, size and origin (rbl__casterId; the
*       instanced stage computes the same): the same in every pass, order, sort, cull and path, with
*       no per-billboard field; batches stream it (4 bytes a vertex) only into casters and receivers.
*       A flat card cannot shadow itself, so whatever orientation the pass gives it and however its
*       normal map bends the normal, its own pixels keep their light; other casters (a crate, the
*       next sprite) shadow it as before. RblShadowDesc.selfShadow drops the identities (depth only:
*       no casters target, 4 B/texel less; billboards then darken themselves where the receiver's
*       PCF footprint meets their own caster).
*       Caster orientation (billboards; FIXED cards keep theirs):
*         light-facing     (default) CAMERA_PLANE cards parallel to the light's view plane,
*                          CAMERA_POSITION and AXIS cards turned toward the light (a directional
*                          light: along its direction; a spot: toward its position): the shadow is a
*                          whole figure stretching away from the light, as an upright object's, in
*                          every direction; the common 2.5D case (characters and trees on a ground,
*                          a sun from the side) casts a full shadow. The silhouette is the sprite's
*                          front image seen from the light (mirrored when the light is behind it).
*         camera-facing    (faceCamera) the billboard call's camera: the shadow is the silhouette the
*                          viewer sees, exact for lights in front or behind; a light from the side sees
*                          the card edge-on (a thin shadow, or the tilt below).
*       AXIS billboards lean until the light sees them at minCastAngle (30 degrees): an upright tree
*       under a light along its axis would be edge-on and cast nothing. They turn about a line across
*       the quad: its lowest edge (a sprite standing on the ground keeps its feet there, whatever its
*       pivot) under a light more than 30 degrees off the axis, moving to mid-height as the light
*       reaches the axis (smoothstep of |l.axis| from cos 30 to 1), where the shadow, centred on the
*       card, no longer depends on which side it leans to: a light passing over the axis moves the
*       shadow continuously (tested in 0.5-degree steps). Light-facing cards turn their front face up
*       toward the light (continuous through the axis); camera-facing ones the nearer face, so their
*       lean changes side where the light crosses the card's plane away from the axis (a jump there:
*       no card hinged above the ground passes from leaning back to leaning forward without standing
*       edge-on). A light within 7.2 degrees of the pivot line tilts them less, none within 0.9.
*       Receiver bias (per light sample, world units, t = texel size at the point), from the
*       rasterised surface's normal (screen derivatives forward, depth neighbours deferred: the card's
*       plane, not its rounded or normal-mapped shading normal), turned toward the light:
*         normal offset    lookup moved along N by normalBias*t*sin(incidence) (shifts edges <= that),
*                          fading out through edge-on (|cos| < 1/20) so it never jumps sides
*         receiver plane   each PCF fetch compares with the receiver's plane extended to that texel
*                          (gradient <= 10 texels per texel): flat ground needs no slope-sized bias
*         depth bias       t*(constantBias + slopeBias*tan(incidence)), tan clamped at 10
*         PCF              k x k texel box over bilinear-weighted comparisons, (k + 1)^2 fetches
*                          (shadowFilter, default 2); k = 1 is hardware 2x2 comparison's footprint
*       Defaults in texels: constant 0.2, slope 0.1, normal 0.25. Outside the map, beyond its far plane,
*       behind a spot light and where nothing was drawn, a point is lit. Deferred: the same lookup; the
*       G-buffer keeps each pixel's identity (RT2 RGBA8 when it receives shadows: 12 B/pixel).
*       Distance code of the casters target: orthographic, the window depth (linear); perspective,
*       log(d/near)/log(far/near) (a step is a fixed share of the distance, as a texel is); 16 bits,
*       its half step added to the depth bias.
*       Contact: where a sprite meets the ground, the ground's texels inside the PCF footprint (k/2 +
*       1 texels) darken its base, as for any receiver meeting another surface (measured: README).
*
*   THIN SPRITES (shaders/transmission.glsl, relief.glsl, shadow_tint.glsl; tests/test_thin.c,
*   deferred: tests/test_deferred_thin.c):
*       Transmission (desc.transmission): a card lit from behind shows the light through it as a thin
*       diffuse sheet: radiance albedo x t x E x clamp((1/4 - N.L)/(5/4), 0, 1) per light (E its
*       irradiance on a surface facing it, N the shading normal on the viewer's side: the back's
*       cosine wrapped so a light edge-on still lights the rim), t = params[RBL_PARAM_TRANSMISSION]
*       x (1 - thickness), thickness from material.thickness (B or A of the material texture; none =
*       0). Lights behind a transmitting card are looked up in their shadow maps (its own caster
*       lets them through). A program without the flag compiles none of it; with it, a material
*       value of 0 returns before any of it per light. Deferred: DEFERRED, thin target.
*       Relief (desc.relief, reliefSteps): the material texture's height channel (material.height)
*       is marched from each shaded texel toward each light in the card's tangent space: reliefSteps
*       evenly spaced samples (16) of the ray up to where it clears height 1 (maps[HEIGHT].value
*       texels, 4); a texel above the ray takes that light away (hard-edged, texel by texel, base
*       level). The reach is capped at 8 climbs (light below 7 degrees over the card), texels are
*       taken as square, the march may read past a frame's edge into its gutter; cross-fading
*       programs march the first frame. Deferred: the geometry pass marches the scene's first 8
*       lights (DEFERRED, thin target); later lights of a deferred frame are not relief-shadowed.
*       Blended casters (RblShadowDesc.transmittance; receivers desc.shadowTransmittance): between
*       RblBeginShadowBlend(coloured) and RblEndShadowBlend inside a shadow pass, draws are smoke or
*       glass: depth-tested against the opaque casters already drawn, they multiply the map's
*       RGBA8 transmittance target by 1 - alpha (grey) or mix(1, colour, alpha) (coloured) and keep
*       the nearest one's distance (8 bits) by min blending; every texel with alpha >= 1/512 casts.
*       A receiver more than 1.5/255 of the depth range behind that distance takes the light times
*       the tint (bilinear over 2 x 2 texels); opaque casters shadow as before. Not on ES 2 (no min
*       blending); single maps only (not omni or cascaded: refused); receivers: forward programs with
*       desc.shadowTransmittance, G-buffers with RblGBufferDesc.shadowTransmittance; skinned
*       Models cannot be blended casters. The target has
*       no caster identities: a blended billboard that receives shadows is tinted where its own
*       light-facing caster card lies in front of it (draw smoke with a program that receives none).
*
*   MATERIAL LAYOUT (RblPackMaterial; bytes per texel at level 0, a mip chain adds 1/3):
*       albedo    RGBA8: sRGB colour, linear alpha                                                  4 B
*       material  RGBA8, linear: RG normal, B specular, A occlusion                                 4 B
*                 normal  RBL_NORMAL_HEMIOCT (default): p = (x,y)/(|x|+|y|+z) stored as (p.x+p.y,
*                         p.x-p.y)*0.5+0.5, best of the 4 floor/ceil codes; RBL_NORMAL_XY: x,y*0.5+0.5,
*                         z rebuilt (weakest at grazing angles). Decode: RblDecodeNormal
*                 B       specular intensity (Blinn-Phong) / perceptual roughness (GGX); absent: 128
*                 A       ambient occlusion; absent: 255
*                 RBL_NORMAL_RGB: RGB normal, A occlusion, no specular channel. None of the three: no
*                 material texture. RblMaterialLayout says which channels hold data (others unsampled).
*       emissive  grey source (r == g == b everywhere): R8 mask, emission = mask x albedo colour    1 B
*                 any coloured texel: RGBA8 sRGB colour                                             4 B
*       9 B/texel with a mask against 16 B for four RGBA8 maps: sprite emission (lamps, eyes, embers)
*       is mostly the surface's own colour lit up, which one byte reproduces.
*       Frames (RblMaterialSource.frames): texels outside every frame take the nearest frame texel in
*       every map and mip level, so filtering never pulls in a neighbour. Mips: raylib's size rule and
*       layout; colour averaged in linear light (alpha-weighted), normals renormalised.
*       Inputs: any uncompressed raylib format; grey/red channel for specular, occlusion and heights;
*       normals n = c*2 - 1 (normalDirectX flips y; |n| < 1/64 is flat; z < 0 clamps to 0).
*       Authoring: RblGenNormalMapFromHeight (heights x strength in texel units: a step of 1.0 between
*       neighbours at strength 1 is 45 degrees; up = toward row 0), RblGenHeightFromLuminance (Rec.709,
*       linear light), RblGenOcclusionFromHeight (darker the deeper a texel lies below its window mean).
*
*   SPRITE SHEETS (RblLoadAtlas / RblLoadAtlasFromMemory; tests/test_atlas.c, test_atlas_render.c, fuzz/):
*       - Read: TexturePacker JSON (hash / array; frame, rotated, trimmed, spriteSourceSize, sourceSize,
*         pivot or Pixi's anchor, scale9Borders, polygon vertices/verticesUV/triangles; meta.image,
*         size, scale; related_multi_packs followed by RblLoadAtlas, plain names beside the file
*         only; the multi-texture (Phaser 3) form: one page per textures[] entry, its normalMap and
*         scale), Aseprite JSON (the same frames; duration ms, frameTags from/to inclusive, direction,
*         repeat as a number or a string, slices: keys with bounds, pivot, center), libGDX text (old
*         xy/size/orig/offset, new bounds/offsets, rotate true/false/any multiple of 90, index: regions
*         sharing a name with index >= 0 are moved together in index order and form a tag; split;
*         page size and pma). Not read: Pixi "animations" lists, TexturePacker's smartupdate and
*         format, libGDX format/filter/repeat (the texture's own settings); libGDX pad is reported
*         once per load (LOG_INFO). Duplicate JSON keys: the last wins (JSON.parse). A libGDX line
*         with a colon is a field when its key is one libGDX writes or the line is indented (old
*         form), else a region name ("ui:button"). Limits, each named in its refusal: nesting 64,
*         coordinates 65536, 64 sheets, text 2^28 bytes, RBL_MAX_ATLAS_ENTRIES JSON values and rows
*         per table, 65535 vertices per polygon; page sizes whole texels 1..65536, scale
*         1/65536..65536; anything else malformed: one line, invalid atlas, nothing kept.
*       - Sheets (RblLoadAtlas): each image is looked for as written (joined to the atlas file's
*         folder unless absolute), then by its base name beside the atlas file, then by the atlas
*         file's own base name with the image's extension; found nowhere, refused with one line
*         naming every path tried. A normal sheet: the file's normalMap (as written, beside by base
*         name, then <sheet>_n), else <sheet>_n.<ext> when it exists (TexturePacker, SpriteIlluminator,
*         Paper2D): RblAtlasPage.normalImage. From memory nothing is looked for: names as written.
*         RblLoadAtlasTextures(&atlas, page, suffix, &material, &desc.material) loads a page into
*         maps[ALBEDO] and its normal sheet (suffix NULL: normalImage; "_x": <sheet>_x.<ext>, which
*         must exist; "": none) into maps[NORMAL], same size required, and fills the layout (RGB
*         normals, premultiplied alpha) the program needs.
*       - One convention: rotated = stored turned 90 degrees clockwise in an h x w block (RblAtlasFrame
*         .block); libGDX's counter-clockwise turn is that plus a half turn, so its .source has both
*         extents negated (both mirrors; a libGDX half turn is both mirrors alone, 270 the clockwise
*         turn); trim and pivot upright, top-left origin (libGDX offsets are counted from the bottom).
*         A frame whose file states no pivot (libGDX never does) stands on its bottom centre (0.5, 1):
*         placed at y = 0 it stands on the floor. RblAtlasBillboard/Instance: size = trim x worldScale
*         / page scale (worldScale: world units per pixel of the art at scale 1, so exports at any
*         meta.scale draw at one size), origin = the pivot from the trimmed quad's bottom-left
*         (outside it when the pivot is), flags' ROTATED bit.
*       - Slices (Aseprite): each key is a sub-frame from its frame to lastFrame. RblAtlasFindSlice
*         (name, frame) finds the key; RblAtlasSliceBillboard/Instance draw it alone: its bounds
*         clipped to the frame's trim, about its pivot (none: its bottom centre). When exactly one
*         slice of an export has pivots, they are also the pivots of the frames its keys cover.
*       - Polygons (TexturePacker; tests/test_polygon.c): RblAtlasFrame.polygon holds the vertices
*         (untrimmed-frame pixels), their sheet texels (inside the block) and triangles (indices <
*         vertexCount), validated on load. Every path draws the triangles, not the trimmed quad: the
*         batch, the immediate path, instanced draws, sprite buffers, shadow casters and the G-buffer.
*         RblAtlasBillboard/Instance put the frame's polygon handle in flags (RBL_FRAME_POLYGON, bits
*         4..23; the atlas owns it until RblUnloadAtlas, after which a billboard still naming it is
*         refused with one line); the texels the file names place each vertex in the quad, so a
*         vertex carries the quad's own position, texture coordinate, normal and tangent there (pixels
*         inside equal the quad's, mirrors and rotated frames included). Rounded normals (roundness >
*         0) use the triangles cut along the quad's diagonal (where its fields meet), flat ones the
*         file's. Batches draw one quad slot per pair of triangles (RblBillboardQuads emits them);
*         instanced draws and sprite buffers compile a polygon variant of the program at their first
*         polygon and draw every instance with the draw's largest polygon's corners (quads use 6, the
*         rest collapse to a point); draws without polygons run the plain program and pay nothing.
*       - 9-slice: RblAtlasFrame.center (scale9Borders, libGDX split) and RblAtlasSlice.center, in
*         canvas pixels (for raylib's DrawTextureNPatch and the like); billboards draw the frame whole.
*       - Premultiplied pages (libGDX pma: RblAtlasPage.premultiplied): RblMaterialLayout
*         .premultipliedAlpha makes the program divide each filtered texel by its alpha before the
*         sRGB decode (the alpha-weighted mean of its neighbours: no dark fringe), light the straight
*         colour and write straight alpha: raylib's default BLEND_ALPHA then composites exactly as
*         premultiplied blending of the lit colour would (do not switch to BLEND_ALPHA_PREMULTIPLY).
*         RblMaterialSource.premultipliedAlpha packs such a sheet: mips averaged as straight colour,
*         stored premultiplied again.
*       - Aseprite exports of several sprites count tags per sprite: a tag lands on the frames named
*         "<tag>:<k>" when the sheet's own indices do not fit those names.
*       - Playback (RblSpritePlayer): per-frame durations (none given: RBL_SPRITE_DEFAULT_FRAME_TIME),
*         forward / reverse / pingpong / pingpong_reverse, a pingpong leg is one pass and the turn
*         frame shows once; loops 0 = the tag's repeat (0 = forever). Whole periods of a large dt are
*         skipped. RblSpriteBlend: next frame and time/duration.
*       - Resident sprites (RblSpriteBuffer; tests/test_sprite_buffer.c): RblLoadSpriteBuffer copies the
*         atlas's frames (source, trimmed quad and pivot per unit of scale, duration) and each tag's
*         timeline (one period in play order, pass ends) into an RGBA32F texture the instanced stage
*         reads with texelFetch (GL 3.3, ES 3, WebGL2; unit RBL_FRAME_TABLE_TEXTURE_UNIT). A sprite
*         with RBL_SPRITE_ANIMATED shows RblUpdateSprite's frame after (time - start) x speed seconds
*         of play (0 before start), with RblSpriteBlend's next frame and weight for crossFade programs
*         (over the current frame's quad: frames of equal trim); loops as RblPlaySprite's, 1..254 or 255
*         forever. Packing: position, scale and start float; rotation in 65536ths of a turn (0.0027
*         degrees at most off), speed a half float (2^-11 relative); tags < 65535, frames < 65536;
*         the clock is a float: keep it small (offset it per level) for millisecond steps past hours.
*         Updates: a range is checked whole, then uploaded; the whole buffer (first 0, count =
*         capacity) is checked as it is written into a second GPU store made on the first such update
*         (twice the GPU memory), swapped in when every sprite passed (draws still reading the other
*         are not waited on; where the context maps buffers). Chunks of 256 sprites keep pivot
*         bounds (updated by RblUpdateSprites); a draw tests them against the pass's clip volume
*         grown by the farthest frame corner x the chunk's largest scale (x |up| for a long
*         CAMERA_PLANE up, x 3 in shadow passes for the AXIS tilt) and draws the visible runs. Draws
*         take no sort (buffer order) and no fades; back faces are drawn in the modes that can show
*         them. Hidden sprites: scale 0.
*       - Cross-fade (RblLitShaderDesc.crossFade; tests/test_fade.c): RblAtlasBillboardFade(&atlas,
*         player.frame, next, w, scale, &billboard, &fade) with next and w from RblSpriteBlend, then
*         RblBatchAddFade(&batch, mat, &billboard, &fade) or RblDrawBillboardFade (instances:
*         RblAtlasInstanceFade, an RblFade beside each) mixes the next frame in by time/duration. The
*         program fetches every map at both frames' UVs (a program without the option fetches once):
*         colour in linear light weighted by coverage (a transparent texel's colour never bleeds in),
*         alpha linearly with the cutoff on the mix, the normal as a world vector (each fetch decoded
*         in its own frame's tangent axes: frames stored rotated differently mix correctly), then
*         renormalised; specular, occlusion and emission by the colour's weight. Weight 0 and 1 are
*         the single frames exactly. Data only where used: the batch's fade stream (32 floats per
*         billboard, attribute location 5 and rblFadeClip) exists from its first billboard with a
*         weight or clip, instanced draws upload RblInstancedDesc.fades (56 bytes an instance, fades[i] with instances[i]) to a
*         second buffer only when it is non-NULL; without data the weight is a constant 0. Shadow
*         passes cut faded casters by the mixed alpha; deferred geometry variants take the option.
*         Frames trimmed differently: each stays where its untrimmed canvas and pivot put it (as
*         RblAtlasBillboard places it alone); the quad covers the union of the two trims, each
*         frame's source stretched over it, and RblFade.clip[k] is frame k's trim in the quad: a
*         fetch outside it is transparent (alpha 0, no colour, normal or emission), and where the
*         frame shown alone (w 0 or 1) or neither lies there is no fragment. Axes a frame covers
*         whole are never clipped: equal trims draw as unclipped.
*       - N-way: RblSpriteViewSector: the eye's direction from the sprite about +Y (0 = +Z, as the
*         facing angle), relative to the facing; sector k covers [k w - w/2, k w + w/2), w = 360/n.
*
*   LIMITATIONS:
*       - Platforms (the GLSL dialect follows rlGetVersion(): 330, 300 es, 120, 100; see PLATFORMS in
*         the README): GL 3.3/4.3 and ES 3/WebGL2 run everything (deferred needs a float colour target,
*         EXT_color_buffer_float on ES; the G-buffer takes 12 bytes/pixel on ES, where two-channel
*         targets are not renderable). GL 2.1 and ES 2/WebGL1 run the forward path (immediate,
*         batched, Models, every BRDF, fog, tonemap, shadows with depth textures); instanced draws and
*         the G-buffer are refused there with one log line; clustered programs fall back to their
*         maxLights slots there (LIGHT GRID).
*       - raylib's own DrawModel/DrawMesh upload colDiffuse, matrices and textures, none of the header's
*         values (roughness, metalness, shininess, specular, emission, alpha cutoff): those need
*         RblDrawModel/RblDrawMesh; a raylib draw with a lit program is noticed at the header's next
*         use of it and logged once per program.
*       - Shadows: an omni map's frame is six passes drawing the casters six times, a cascaded map's
*         one pass per cascade (rlgl has no layered or geometry-shader rendering); cascades fit one
*         camera per map, directional lights only; comparison in the shader (rlgl exposes no GL_TEXTURE_COMPARE_MODE). RblEndShadowMap restores
*         the target, viewport and matrices it found but leaves the depth test off, culling on and
*         colour blending on (as EndMode3D and raylib's default): run shadow passes before BeginMode3D
*         (inside BeginTextureMode is fine).
*       - Caster identities are 16 bits: a billboard is not shadowed by another whose pivot, size and
*         origin hash alike (1 pair in 65536), nor by one with the very same pivot, size and origin.
*         The map keeps the nearest caster per texel: where a billboard's own light-facing card lies
*         between the light and its visible card, another caster between the two cards is hidden
*         (within half the card's width of it). Camera-facing AXIS casters change the side they lean
*         to where the light crosses the card's plane away from the axis (light-facing ones do not).
*         ES 2 without highp fragments: the casters target's 16-bit code loses precision (mediump);
*         without OES_standard_derivatives the bias follows the interpolated vertex normal.
*       - Deferred: one BRDF and light feature set per G-buffer (a geometry variant of another brdf is
*         refused at draw); Blinn-Phong specular colour folded to its luminance, its intensity clamped
*         to 1.996 and shininess to 2048 in the G-buffer; at most RBL_MAX_LIGHTS unbounded lights
*         (directional, range 0); a G-buffer loaded with size 0 takes its target's size at each
*         RblBeginGBuffer (the screen, or the render texture of BeginTextureMode) and RblEndGBuffer
*         returns to that target; a fixed size resolved into another size is scaled (logged). The frame's
*         ambient is the scene's at RblBeginGBuffer: set the scene before it (a later RblSetScene
*         changes the lights of the frame, not its ambient).
*       - No image-based lighting: GGX ambient uses F0 as the environment's specular reflectance;
*         metalness is one value per material (the packed layout has no channel for it).
*       - Polygon frames: a cross-fade (RblBatchAddFade, RblInstancedDesc.fades, crossFade programs on
*         sprite buffers) draws the quad (the union of two frames' trims); 2^20 - 1 polygon handles
*         are live at once (an atlas load beyond is refused); flags from 2^24 up carry no polygon (the
*         instanced stage reads flags as a float). An instanced draw mixing small and large polygons
*         runs the vertex stage for the largest on every instance; on llvmpipe the thinner triangles
*         cost about as much as the fragments saved (make bench: polygon rows).
*       - A draw that shows a quad's back turns face culling back on after itself (raylib's default):
*         rlgl cannot report the caller's state.
*       - Instanced draws share facing, up, axis and roundness; own FIXED frames go through a batch.
*       - Cross-fade clips each frame to its trim by a test in the fragment stage: on ES 2 without
*         highp fragments (mediump) the trim edges are placed to about 1/1000 of the quad.
*       - Thin sprites deferred: a 5th render target (not on contexts with 4 draw buffers: many ES 3 /
*         WebGL2 devices); relief self-shadow for the scene's first 8 lights only, as the scene
*         stood during the geometry pass; a relief height comes from a packed
*         channel (RblPackMaterial does not derive one from the normal map: pack the height as the
*         specular or occlusion source into B or A).
*       - rlgl's matrix stack (rlPushMatrix/rlTranslatef) does not apply: vertices are world space.
*
*   CONFIGURATION:
*       #define RBILLBOARD_LIT_IMPLEMENTATION
*           Generates the implementation in the including file (exactly one translation unit).
*       #define RBL_NO_ATLAS
*           Leaves out the sprite-sheet module (atlas readers, player, sectors: SPRITE SHEETS); the
*           rest of the header does not depend on it.
*       #define RBL_NO_MAPPED_BATCH
*           Batches keep their records on the CPU and upload them at RblEndBatch (by default the adds
*           write them into the mapped GPU buffer where the context maps buffers: GL 3.3, ES 3).
*       #define RBL_NO_SIMD
*           Billboard checks and culling in plain C (by default SSE2 where the compiler targets it).
*       #define RBL_INSTRUMENTS
*           Adds what the tests and benchmarks measure with: RblMeasureNormalEncoding, the G-buffer's
*           naiveFullscreen baseline and forced-failure hooks (not for games).
*       #define RBL_MAX_LIGHTS 64
*           Light slots a lit program may compile (a slot costs 2 vec4 uniforms, 3-4 with spot cones /
*           classic falloff); also the unbounded lights one RblDrawDeferredLights accepts.
*       #define RBL_SHADER_CACHE_SIZE 1024
*           Programs the registry holds: one per lit Shader loaded, casters while a shadow map is loaded,
*           5 passes per distinct G-buffer desc. A load beyond it fails with a log line.
*       #define RBL_BATCH_DEFAULT_CAPACITY 1024
*           Billboards a batch, or instances an instance buffer, reserves when loaded with 0.
*       #define RBL_MAX_BATCH_BILLBOARDS 2097152, RBL_MAX_INSTANCES 2097152
*           Limits of a batch and of an instance buffer / one instanced draw (their byte sizes fit an int).
*       #define RBL_MAX_SCENE_LIGHTS 65536, RBL_MAX_LIGHT_INTENSITY 1e12f
*           Lights one RblScene may list, and the largest intensity (sums of lights stay finite).
*       #define RBL_MAX_TARGET_SIZE 16384
*           Largest G-buffer side and shadow-map size (the driver's own maximum applies too).
*       #define RBL_MAX_OCCLUSION_RADIUS 256
*           Largest RblGenOcclusionFromHeight radius, in texels.
*       #define RBL_MAX_ATLAS_ENTRIES 16777216
*           JSON values one atlas text may hold (32 to 38 per TexturePacker frame: 440k-520k frames),
*           and rows of every atlas table (frames, tags, slice keys, polygon points and indices);
*           1..2^26. The reader holds the text's values at once (20 bytes each).
*           Input beyond any limit is refused with one log line; world positions and camera vectors
*           must stay below 1.15e18 (2^60) in magnitude, so squared lengths fit in a float.
*       #define RBL_SPRITE_DEFAULT_FRAME_TIME 0.1f
*           Seconds a frame shows where its atlas states no duration (libGDX, TexturePacker).
*       #define RBL_MAX_SHADOWS 4
*           Shadow maps a scene may list and a receiver sample (desc.shading.shadowMaps); at most 4.
*       #define RBL_SCENE_DEPTH_TEXTURE_UNIT 11
*           Texture unit soft particles read the scene depth from (RblScene.depth, RblEndSceneDepth).
*       #define RBL_SHADOW_TEXTURE_UNIT 12
*           Scene shadow map k goes to texture unit 12 + k (raylib's material maps use 0..10, the
*           scene depth 11; GL 3.3 promises 16).
*       #define RBL_FRAME_TABLE_TEXTURE_UNIT 16
*           Texture unit a sprite buffer's frame table is read from by the vertex stage (GL 3.3, ES 3
*           and WebGL2 promise 32 units in all).
*       #define RBL_MAX_BONES 128
*           Bone matrices a skinned program holds (4 vertex uniform vectors each; 1..256).
*       #define RBL_GPU_SKINNING 1
*           raylib was built with SUPPORT_GPU_SKINNING (default: SUPPORT_GPU_SKINNING where defined,
*           else 0, and desc.skinning is refused: without it Mesh.vboId has no bone buffers).
*       #define RBL_SHADOW_MAX_FILTER 6
*           Largest PCF footprint (desc.shading.shadowFilter), in texels per side.
*       #define RBL_SHADOW_TINT_TEXTURE_UNIT 6
*           Shadow map k's transmittance target goes to unit 6 + k in programs with
*           desc.shadowTransmittance (bound at each of their draws; a Model material with textures
*           in raylib's HEIGHT..PREFILTER slots would take those units while DrawMesh draws it).
*       #define RBL_MAX_RELIEF_STEPS 64
*           Largest relief self-shadow march (desc.reliefSteps), samples per light.
*       #define RBL_LIGHT_GRID_TEXTURE_UNIT 17
*           Clustered programs (desc.clustered) read the light data from unit 17 and the grid from 18.
*       #define RBL_LIGHT_GRID_MAX_CELLS 16384, RBL_LIGHT_GRID_CELL_LIGHTS 128
*           Cells of the scene's light grid, and lights one cell lists (the scene's first lights
*           reaching it: LIGHT GRID); cells x lights stays below 2^22 (one 2048 x 2048 float texture).
*       #define RBL_MALLOC / RBL_CALLOC / RBL_REALLOC / RBL_FREE
*           Custom allocator: define all four or none.
*       RBL_ZERO (defined by the header)
*           Zero initialiser for any struct, in C99 and C++11 alike: `RblLitShaderDesc desc = RBL_ZERO;`
*           (`{ 0 }` in C, `{}` in C++, where `{ 0 }` warns under -Wextra and designated fields need C++20).
*       #define RBLAPI
*           Decoration for public functions; BUILD_LIBTYPE_SHARED / USE_LIBTYPE_SHARED select
*           __declspec(dllexport/dllimport) on Windows, as in raylib.
*
*   VERSIONS HISTORY: (migration tables: CHANGELOG.md)
*       0.5 (unreleased)  ADDED: sprite-sheet atlases (TexturePacker, Aseprite, libGDX), the sprite player,
*                                N-way sectors, cross-fades, slices, premultiplied pages, normal sheets
*                         ADDED: GPU-skinned Models; translucent sorting; soft particles (RblBeginSceneDepth)
*                         ADDED: run-time GLSL dialects (GL 3.3, ES 3, ES 2, GL 2.1, WebGL 1 and 2)
*                         ADDED: sprites never shadow themselves (caster identities); orthographic cameras
*                         ADDED: RblClose in any order; stale copies of every value type refused by id
*                         ADDED: RBL_VERSION, RBL_VERSION_MAJOR/MINOR/PATCH
*                         CHANGED: the G-buffer keeps one 56-bit word and a float depth
*                         CHANGED: shadow casters face the light by default (RblShadowDesc.faceCamera)
*                         ADDED: batch culling (RblBatch.culled, .noCull): off-view billboards never expanded
*                         CHANGED: RblGBufferView -> RblGBufferOutput; private members behind .state
*                         CHANGED: a cross-fade travels beside the billboard (RblBatchAddFade,
*                                  RblDrawBillboardFade): RblBillboard back to 0.3's 88 bytes
*                         REMOVED: RblShadowDesc.faceLight (the default now)
*                         CHANGED: RblShading: the lighting fields lit programs and G-buffers share;
*                                  RblLightFeatures() -> RblGetLightFeatures()
*                         REMOVED: RblSpriteFade (a fade is set up one way: RblAtlasBillboardFade /
*                                  RblAtlasInstanceFade of RblSpriteBlend's frame and weight)
*       0.4 (2026-11-23)  CHANGED: the 1.0 API shape: a lit program is a raylib Shader of compiled
*                                  features; values travel with the Material; one RblScene a frame
*                         ADDED: RblDrawModel, RblDrawMesh; RBL_ZERO; C++11..23; the contract suite
*                         REMOVED: RblLitShader, RblSetLights, RblSetFog, RblSetExposure, RblSetShadows
*       0.3 (2026-11-23)  CHANGED: faster CPU geometry (facing frames reused, exact-degree rotation)
*       0.2 (2026-11-23)  ADDED: directional and spot shadow maps, cut-out casters, forward and deferred
*       0.1 (2026-11-22)  ADDED: first release: facing modes, immediate/batched/instanced paths,
*                                packed maps, forward lighting, the deferred helper
*
*   DEPENDENCIES:
*       raylib 6.0 or later (raylib.h, rlgl.h, raymath.h), any of its GL backends: 3.3, 4.3, ES 3, ES 2, 2.1
*
*   LICENSE: zlib/libpng
*
*   Copyright (c) 2026 rbillboard_lit contributors
*
*   This software is provided "as-is", without any express or implied warranty. In no event
*   will the authors be held liable for any damages arising from the use of this software.
*
*   Permission is granted to anyone to use this software for any purpose, including commercial
*   applications, and to alter it and redistribute it freely, subject to the following restrictions:
*
*     1. The origin of this software must not be misrepresented; you must not claim that you
*     wrote the original software. If you use this software in a product, an acknowledgment
*     in the product documentation would be appreciated but is not required.
*
*     2. Altered source versions must be plainly marked as such, and must not be misrepresented
*     as being the original software.
*
*     3. This notice may not be removed or altered from any source distribution.
*
**********************************************************************************************/

#ifndef RBILLBOARD_LIT_H
#define RBILLBOARD_LIT_H

#include "raylib.h"

#if !defined(RAYLIB_VERSION_MAJOR) || (RAYLIB_VERSION_MAJOR < 6)
    #error "rbillboard_lit.h needs raylib 6.0 or later, and the raylib.h included is older: update raylib (or put raylib 6's include directory first)"
#endif

#define RBL_VERSION_MAJOR 0
#define RBL_VERSION_MINOR 5
#define RBL_VERSION_PATCH 0
#define RBL_VERSION "0.5.0"                     // CHANGELOG.md lists what each version changed
#define RBILLBOARD_LIT_VERSION_MAJOR RBL_VERSION_MAJOR     // The same under the header's name (0.1..0.4 spelling)
#define RBILLBOARD_LIT_VERSION_MINOR RBL_VERSION_MINOR
#define RBILLBOARD_LIT_VERSION_PATCH RBL_VERSION_PATCH
#define RBILLBOARD_LIT_VERSION RBL_VERSION

// Function specifiers for a shared library build on Windows (as raylib's BUILD_LIBTYPE_SHARED)
#ifndef RBLAPI
    #if defined(_WIN32) && defined(BUILD_LIBTYPE_SHARED)
        #define RBLAPI __declspec(dllexport)     // Building the library as a Win32 shared library (.dll)
    #elif defined(_WIN32) && defined(USE_LIBTYPE_SHARED)
        #define RBLAPI __declspec(dllimport)     // Using the library as a Win32 shared library (.dll)
    #else
        #define RBLAPI                           // Functions defined as 'extern' by default (implicit specifiers)
    #endif
#endif

//----------------------------------------------------------------------------------
// Defines and Macros   >>config
//----------------------------------------------------------------------------------
// Zero initialiser valid in C99 and C++11 alike (`RblBillboard card = RBL_ZERO;`, then set fields):
// C's universal `{ 0 }` draws -Wmissing-field-initializers in C++, whose `{}` is not C99
#if defined(__cplusplus)
    #define RBL_ZERO {}
#else
    #define RBL_ZERO { 0 }
#endif
#ifndef RBL_MAX_LIGHTS
    #define RBL_MAX_LIGHTS 64                   // Light slots a lit shader may compile in
#endif
#ifndef RBL_SHADER_CACHE_SIZE
    #define RBL_SHADER_CACHE_SIZE 1024          // Programs the registry may hold (lit programs, casters, G-buffer passes)
#endif
#ifndef RBL_BATCH_DEFAULT_CAPACITY
    #define RBL_BATCH_DEFAULT_CAPACITY 1024     // Billboards reserved by RblLoadBatch(0)
#endif
#ifndef RBL_MAX_BATCH_BILLBOARDS
    #define RBL_MAX_BATCH_BILLBOARDS 2097152    // Billboards one batch may hold (2^21: 436 MB of vertices)
#endif
#ifndef RBL_MAX_INSTANCES
    #define RBL_MAX_INSTANCES 2097152           // Instances one buffer may hold and one draw may take (2^21)
#endif
#ifndef RBL_MAX_SCENE_LIGHTS
    #define RBL_MAX_SCENE_LIGHTS 65536          // Lights one RblScene may hold (forward lights the first maxLights; clustered programs all)
#endif
#ifndef RBL_MAX_TARGET_SIZE
    #define RBL_MAX_TARGET_SIZE 16384           // Largest G-buffer side and shadow-map size (also capped by the driver)
#endif
#ifndef RBL_MAX_LIGHT_INTENSITY
    #define RBL_MAX_LIGHT_INTENSITY 1e12f       // Largest RblLight.intensity (sums of lights stay finite in float)
#endif
#ifndef RBL_MAX_OCCLUSION_RADIUS
    #define RBL_MAX_OCCLUSION_RADIUS 256        // Largest RblGenOcclusionFromHeight radius in texels
#endif
#ifndef RBL_MAX_ATLAS_ENTRIES
    #define RBL_MAX_ATLAS_ENTRIES 16777216      // JSON values one atlas text may hold, and rows of each atlas table (2^24; at most 2^26)
#endif
#ifndef RBL_SPRITE_DEFAULT_FRAME_TIME
    #define RBL_SPRITE_DEFAULT_FRAME_TIME 0.1f  // Seconds a frame shows where the atlas gives no duration (libGDX, TexturePacker)
#endif
#ifndef RBL_MAX_SHADOWS
    #define RBL_MAX_SHADOWS 4                   // Shadow maps one lit shader may sample (at most 4)
#endif
#ifndef RBL_SCENE_DEPTH_TEXTURE_UNIT
    #define RBL_SCENE_DEPTH_TEXTURE_UNIT 11     // The scene depth soft particles read (RblScene.depth)
#endif
#ifndef RBL_SHADOW_TEXTURE_UNIT
    #define RBL_SHADOW_TEXTURE_UNIT 12          // Shadow map k is bound to unit 12 + k (raylib's material maps use 0..10, the scene depth 11)
#endif
#ifndef RBL_FRAME_TABLE_TEXTURE_UNIT
    #define RBL_FRAME_TABLE_TEXTURE_UNIT 16     // A sprite buffer's frame table (vertex stage; above the shadow maps' units)
#endif
#ifndef RBL_SHADOW_MAX_FILTER
    #define RBL_SHADOW_MAX_FILTER 6             // Largest PCF footprint in texels per side
#endif
#ifndef RBL_SHADOW_TINT_TEXTURE_UNIT
    #define RBL_SHADOW_TINT_TEXTURE_UNIT 6      // Map k's transmittance target on unit 6 + k (shadowTransmittance receivers; raylib's HEIGHT..PREFILTER slots)
#endif
#ifndef RBL_MAX_RELIEF_STEPS
    #define RBL_MAX_RELIEF_STEPS 64             // Largest relief march (desc.reliefSteps), samples per light
#endif
#ifndef RBL_LIGHT_GRID_TEXTURE_UNIT
    #define RBL_LIGHT_GRID_TEXTURE_UNIT 17      // Clustered programs: light data on this unit, the grid on the next
#endif
#ifndef RBL_LIGHT_GRID_MAX_CELLS
    #define RBL_LIGHT_GRID_MAX_CELLS 16384      // Cells of the scene's light grid
#endif
#ifndef RBL_LIGHT_GRID_CELL_LIGHTS
    #define RBL_LIGHT_GRID_CELL_LIGHTS 128      // Lights one grid cell lists (the scene's first reaching it)
#endif
#ifndef RBL_MAX_BONES
    #define RBL_MAX_BONES 128                   // Bone matrices a skinned program holds (4 uniform vectors each; at most 256)
#endif
#ifndef RBL_GPU_SKINNING
    #if defined(SUPPORT_GPU_SKINNING)
        #define RBL_GPU_SKINNING SUPPORT_GPU_SKINNING   // raylib's build flag, when the build passes it on
    #else
        #define RBL_GPU_SKINNING 0              // raylib built without it: Mesh.vboId has no bone buffers
    #endif
#endif

//----------------------------------------------------------------------------------
// Types and Structures Definition   >>types
//----------------------------------------------------------------------------------
// How a billboard orients itself
typedef enum {
    RBL_FACING_CAMERA_PLANE = 0,    // Parallel to the view plane (raylib's DrawBillboard)
    RBL_FACING_CAMERA_POSITION,     // Each billboard turns toward the eye
    RBL_FACING_AXIS,                // Turns toward the eye around a locked axis (default +Y)
    RBL_FACING_FIXED                // World orientation given by normal and up
} RblFacing;

// Billboard flags
typedef enum {
    RBL_FRAME_ROTATED = 1,          // Atlas frame stored rotated 90 degrees clockwise (texture packers)
    RBL_ROUND_CYLINDER = 2,         // Rounded normals bend around the up axis only (default: sphere)
    RBL_FRAME_POLYGON = 0xFFFFF0    // Bits 4..23: a loaded atlas's polygon frame (RblAtlasBillboard sets them; 0 = the quad), drawn as its triangles
} RblBillboardFlags;

// Cross-fade to a second atlas frame (a program with RblLitShaderDesc.crossFade mixes the two); zero = none
typedef struct RblFade {
    Rectangle source;               // Second frame in texels, as RblBillboard.source (zero = whole texture), drawn over the first's quad
    float weight;                   // Share of the second frame, 0..1 (0 = the first alone; NaN/Inf or outside refused)
    unsigned int flags;             // The second frame's RBL_FRAME_ROTATED bit (other bits ignored)
    Rectangle clip[2];              // Where each frame ([0] first, [1] second) is drawn: its trimmed part of the quad as fractions (x, y from the picture's top-left, width, height); zero = the whole quad (RblAtlasBillboardFade fills these)
} RblFade;

// One billboard; zero fields take their defaults
typedef struct RblBillboard {
    Vector3 position;               // World position of the pivot
    Vector2 size;                   // World size; a negative component mirrors the image
    Vector2 origin;                 // Pivot, world units from the bottom-left corner (DrawBillboardPro)
    float rotation;                 // Degrees, counter-clockwise as seen from the front
    Rectangle source;               // Atlas frame in texels (zero = whole texture); negative extent mirrors
    Color tint;                     // Vertex colour (all zero = WHITE)
    int facing;                     // RblFacing
    Vector3 up;                     // CAMERA_PLANE: up vector (zero = camera up); FIXED: up (zero = +Y)
    Vector3 axis;                   // AXIS: locked axis (zero = +Y); FIXED: facing normal (zero = +Z)
    float roundness;                // 0 = flat normal, 1 = fully rounded (see RBL_ROUND_CYLINDER)
    unsigned int flags;             // RblBillboardFlags
} RblBillboard;

// Vertex layout of the batched path where it draws vertices (attribute locations are raylib's defaults)
typedef struct RblVertex {
    float position[3];              // location 0: vertexPosition
    float texcoord[2];              // location 1: vertexTexCoord
    float normal[3];                // location 2: vertexNormal
    float tangent[4];               // location 4: vertexTangent (xyz: +U, w: handedness)
    unsigned char color[4];         // location 3: vertexColor
} RblVertex;

// Camera frame derived once per batch (degenerate cameras already resolved)
typedef struct RblCameraFrame {
    Vector3 eye;                    // Camera position
    Vector3 right;                  // View matrix row 0 (unit)
    Vector3 up;                     // View matrix row 1 (unit)
    Vector3 back;                   // View matrix row 2 (unit, from target toward the eye)
    bool orthographic;              // Parallel view (CAMERA_ORTHOGRAPHIC): the eye is at infinity along back, facing modes turn toward back
} RblCameraFrame;

// How RblEndBatch orders and passes a batch's billboards (RblBatch.sort)
typedef enum {
    RBL_SORT_NONE = 0,              // Submission order (opaque and alpha-tested billboards)
    RBL_SORT_BACK_TO_FRONT,         // Farthest quad centre first along the view axis (blended billboards)
    RBL_SORT_HYBRID                 // Solid texels first (depth tested and written), then the fringe back to front without depth writes
} RblSortMode;

// Batched billboards: CPU vertices, one GPU upload per RblEndBatch(), one draw per material run
typedef struct RblBatch {
    int sort;                       // RblSortMode, read by RblEndBatch (0 = submission order)
    float solidAlpha;               // RBL_SORT_HYBRID: alpha from which a texel is solid (0 = 1.0, fully opaque only)
    bool noCull;                    // Read by RblBeginBatch: true = keep billboards outside the view (default: culled)
    int capacity;                   // Billboards reserved (CPU and GPU; doubles with a log line when full)
    int count;                      // Billboards added since RblBeginBatch() (culled ones included)
    int skipped;                    // Billboards skipped for bad input since RblBeginBatch()
    int culled;                     // Of count, billboards outside the view (camera, or a shadow pass's light): neither expanded nor drawn
    unsigned int id;                // Object id: a stale copy is recognised by it (0 = not loaded)
    struct rbl__BatchState *state;  // The header's: vertices, material runs, GL buffers, camera frame (NULL = not loaded)
} RblBatch;

// One instance of the instanced path: per-instance data only (56 bytes), the quad is expanded
// on the GPU with the same math as RblBillboardVertices()
typedef struct RblInstance {
    Vector3 position;               // World position of the pivot
    float rotation;                 // Degrees, counter-clockwise as seen from the front
    Vector2 size;                   // World size; a negative component mirrors the image
    Vector2 origin;                 // Pivot, world units from the bottom-left corner
    Rectangle source;               // Atlas frame in texels (zero = whole texture); negative extent mirrors
    Color tint;                     // Vertex colour (all zero = WHITE)
    unsigned int flags;             // RblBillboardFlags
} RblInstance;

// What one instanced draw shares across its instances; zero means default
typedef struct RblInstancedDesc {
    int facing;                     // RblFacing for every instance
    Vector3 up;                     // As RblBillboard.up
    Vector3 axis;                   // As RblBillboard.axis
    float roundness;                // As RblBillboard.roundness
    int sort;                       // RblSortMode by each instance's pivot depth (0 = the array's order); solid alpha 1
    const RblFade *fades;           // NULL = no fade; else fades[i] goes with instances[i] (the draw's count of them), uploaded to a second buffer
} RblInstancedDesc;

// GPU instance buffer plus a staging copy (validated)
typedef struct RblInstanceBuffer {
    int capacity;                   // Instances reserved (doubles with a log line when a draw needs more)
    int skipped;                    // Instances skipped for bad input in the last draw
    unsigned int id;                // Object id: a stale copy is recognised by it (0 = not loaded)
    struct rbl__InstanceBufferState *state; // The header's: GPU buffers, staging copy (NULL = not loaded)
} RblInstanceBuffer;

// One resident sprite of an RblSpriteBuffer (32 bytes): an atlas frame, or a tag played on the GPU
// from the draw's clock; size, origin, source and per-frame times come from the buffer's frame table
typedef struct RblSpriteInstance {
    Vector3 position;               // World position of the pivot (float: corners keep float precision)
    float scale;                    // World units per pixel of the art, as worldScale (0 = hidden)
    float start;                    // Clock time (RblDrawSpriteBuffer's) the tag started at
    Color tint;                     // Vertex colour (all zero = WHITE)
    unsigned short rotation;        // Degrees x 65536/360 (RblMakeSprite rounds; 0.0027 degrees at most off)
    unsigned short frame;           // Atlas frame; RBL_SPRITE_ANIMATED: tag (0xFFFF = every frame, forward)
    unsigned short speed;           // Playback rate, IEEE half-float bits (finite, >= 0; 0 = held on its first frame)
    unsigned short mode;            // RblSpriteMode bits, loops << 8 (0 = the tag's repeat, 255 = forever)
} RblSpriteInstance;

// RblSpriteInstance.mode bits
typedef enum {
    RBL_SPRITE_FLIP_X = 1,          // Mirror left-right about the pivot
    RBL_SPRITE_FLIP_Y = 2,          // Mirror top-bottom about the pivot
    RBL_SPRITE_ROUND_CYLINDER = 4,  // As RBL_ROUND_CYLINDER
    RBL_SPRITE_ANIMATED = 8         // frame is a tag played from start at speed (RblSpritePlayer's rules)
} RblSpriteMode;

// Resident sprites: uploaded once, ranges updated, drawn (culled by chunk, animated on the GPU) per call
typedef struct RblSpriteBuffer {
    int capacity;                   // Sprites it holds (fixed at load)
    int count;                      // Sprites drawn: one past the highest index updated
    unsigned int id;                // Object id: a stale copy is recognised by it (0 = not loaded)
    struct rbl__SpriteBufferState *state; // The header's: GPU buffer, frame table, chunk bounds (NULL = not loaded)
} RblSpriteBuffer;

// Normal encodings (packed material texture, or a plain normal map)
typedef enum {
    RBL_NORMAL_NONE = 0,            // No normal map: the geometry normal, nothing sampled
    RBL_NORMAL_HEMIOCT,             // Hemi-octahedral in two 8-bit channels, precise encoder (packing default)
    RBL_NORMAL_XY,                  // X and Y in two 8-bit channels, Z rebuilt as sqrt(max(0, 1 - x*x - y*y))
    RBL_NORMAL_RGB                  // Plain RGB tangent-space map (raylib's MATERIAL_MAP_NORMAL as authored)
} RblNormalEncoding;

// A channel of the packed material texture holding a scalar map (RblMaterialLayout.height, .thickness)
typedef enum {
    RBL_CHANNEL_NONE = 0,           // Absent: nothing sampled
    RBL_CHANNEL_B,                  // Blue (free when the layout has no specular map and the normal is two-channel)
    RBL_CHANNEL_A                   // Alpha (free when the layout has no occlusion)
} RblMaterialChannel;

// Emissive representations of a packed material
typedef enum {
    RBL_EMISSIVE_NONE = 0,          // No emission, nothing sampled
    RBL_EMISSIVE_MASK,              // 8-bit grey mask (1 byte/texel): emission = mask x albedo colour
    RBL_EMISSIVE_RGB                // Own colour (sRGB RGBA8, 4 bytes/texel)
} RblEmissiveLayout;

// What a packed material holds; it also selects the lit shader variant (absent maps are never sampled)
typedef struct RblMaterialLayout {
    int normalEncoding;             // RblNormalEncoding of the material texture's RG (RGB for RBL_NORMAL_RGB)
    bool specular;                  // Material texture B: specular intensity (or roughness), linear
    bool occlusion;                 // Material texture A: ambient occlusion, linear
    int emissive;                   // RblEmissiveLayout of the emissive texture
    bool premultipliedAlpha;        // Albedo texels hold colour x alpha (libGDX pma): divided back after filtering, before lighting
    int height;                     // RblMaterialChannel of the material texture holding height 0..1 (relief self-shadow; 0 = none)
    int thickness;                  // RblMaterialChannel holding thickness 0..1 (transmission x (1 - thickness); 0 = none)
} RblMaterialLayout;

// Packing input: raylib Images of one size (any format raylib converts); data == NULL = absent
typedef struct RblMaterialSource {
    Image albedo;                   // Required: colour (sRGB) with alpha
    Image normal;                   // Tangent-space normal map (RGB, OpenGL convention unless normalDirectX)
    Image specular;                 // Specular intensity or roughness (grey; red channel of a colour image)
    Image occlusion;                // Ambient occlusion (grey)
    Image emissive;                 // Emission: colour (sRGB), or grey = a mask
    bool normalDirectX;             // Normal map is DirectX convention (+Y down): flipped on packing
    int normalEncoding;             // RblNormalEncoding to pack into (0 = RBL_NORMAL_HEMIOCT)
    const Rectangle *frames;        // Atlas frames whose edge texels are dilated into the gutters (NULL = none)
    int frameCount;                 // Number of frames
    bool mipmaps;                   // Build mip chains (normals renormalised, colour averaged in linear light)
    float alphaCoverage;            // With mipmaps: keep the share of texels at or above this alpha cutoff on every level (0 = off)
    bool premultipliedAlpha;        // The albedo holds colour x alpha (libGDX pma); kept so (mips too), layout.premultipliedAlpha set
} RblMaterialSource;

// Packing output (CPU Images; upload with LoadTextureFromImage or RblLoadPackedTextures)
typedef struct RblPackedMaterial {
    Image albedo;                   // RGBA8 sRGB, gutters dilated
    Image material;                 // RGBA8: RG normal, B specular, A occlusion (data == NULL if nothing to store)
    Image emissive;                 // R8 mask or RGBA8 sRGB (data == NULL if none)
    RblMaterialLayout layout;       // What is stored where
} RblPackedMaterial;

#if defined(RBL_INSTRUMENTS)
// Angular error of a normal encoding, in degrees (an instrument of the tests and benchmarks)
typedef struct RblNormalErrorStats {
    double mean;                    // Mean angular error
    double p99;                     // 99th percentile
    double max;                     // Maximum
    int count;                      // Normals measured
} RblNormalErrorStats;

// The scene's light grid as the last build made it (an instrument of the tests and benchmarks)
typedef struct RblLightGridStats {
    int cells[3];                   // Cells along x, y, z (0 = no bounded light in the grid)
    float cellSize;                 // World size of a cell
    Vector3 origin;                 // World corner of cell (0, 0, 0)
    int unbounded;                  // Lights lit everywhere (directional, range 0, or as large as the light set)
    int entries;                    // Light entries over all cells
    int fullestCell;                // Most lights reaching one cell (before the cap)
    int cappedCells;                // Cells that reached more than RBL_LIGHT_GRID_CELL_LIGHTS lights
    int builds;                     // Grids built since the header started (a scene no clustered program reads builds none)
} RblLightGridStats;
#endif

// Light types (RblLight.type)
typedef enum {
    RBL_LIGHT_POINT = 0,            // Omnidirectional, from position
    RBL_LIGHT_DIRECTIONAL,          // Parallel rays along direction (sun); no falloff
    RBL_LIGHT_SPOT                  // Cone from position along direction, smooth inner/outer edge
} RblLightType;

// Distance falloff of point and spot lights (RblLight.falloff)
typedef enum {
    RBL_FALLOFF_WINDOWED = 0,       // I*saturate(1 - (d/range)^4)^2/max(d^2, 1e-4) (UE4, Filament)
    RBL_FALLOFF_CLASSIC             // I/(constant + linear*d + quadratic*d^2), times the range window when range > 0
} RblFalloff;

// Light features a lit shader variant compiles in (RblShading.lightFeatures; bit flags)
typedef enum {
    RBL_LIGHT_FEATURE_POINT = 1,           // Point lights (windowed falloff)
    RBL_LIGHT_FEATURE_DIRECTIONAL = 2,     // Directional lights
    RBL_LIGHT_FEATURE_SPOT = 4,            // Spot cones
    RBL_LIGHT_FEATURE_CLASSIC_FALLOFF = 8  // Constant/linear/quadratic attenuation
} RblLightFeature;

// Reflectance models (RblShading.brdf)
typedef enum {
    RBL_BRDF_LAMBERT = 0,           // Diffuse only
    RBL_BRDF_BLINN_PHONG,           // Lambert + normalised Blinn-Phong: specular intensity (map or value) and shininess
    RBL_BRDF_GGX                    // Cook-Torrance: GGX, Smith height-correlated visibility, Schlick Fresnel; roughness, metalness
} RblBrdf;

// Fog modes (RblFog.mode), by distance d to the eye
typedef enum {
    RBL_FOG_NONE = 0,
    RBL_FOG_LINEAR,                 // Visible fraction 1 - (d - start)/(end - start), clamped
    RBL_FOG_EXP,                    // exp(-density*d)
    RBL_FOG_EXP2                    // exp(-(density*d)^2)
} RblFogMode;

// Tone mapping applied after exposure, before the display encoding (RblShading.tonemap)
typedef enum {
    RBL_TONEMAP_NONE = 0,           // Clamp
    RBL_TONEMAP_REINHARD,           // c/(1 + c)
    RBL_TONEMAP_ACES                // ACES filmic fit (Narkowicz 2015)
} RblTonemap;

// What a lit program writes instead of the lit colour (RblLitShaderDesc.debugOutput)
typedef enum {
    RBL_DEBUG_OUTPUT_NONE = 0,      // The lit colour
    RBL_DEBUG_OUTPUT_TANGENT_NORMAL, // The tangent-space normal the maps give
    RBL_DEBUG_OUTPUT_WORLD_NORMAL,  // The shading normal in world space
    RBL_DEBUG_OUTPUT_SPECULAR,      // The specular map
    RBL_DEBUG_OUTPUT_OCCLUSION,     // The occlusion map
    RBL_DEBUG_OUTPUT_COUNT
} RblDebugOutput;

// Light: a plain value; arrays of them are owned by the caller (no hidden global state)
typedef struct RblLight {
    Vector3 position;               // World position (point, spot)
    Color color;                    // Colour (sRGB like every raylib Color; lit in linear light)
    float intensity;                // Scale of color; >= 0
    float range;                    // Distance where the light fades to zero (0 = no window)
    int type;                       // RblLightType (0 = point)
    Vector3 direction;              // Direction the light travels (directional, spot); any non-zero length
    float innerAngle;               // Spot: half-angle of the full-intensity core, degrees (0..outer)
    float outerAngle;               // Spot: half-angle where it reaches zero, degrees (0 = 30; at most 90)
    int falloff;                    // RblFalloff (0 = windowed inverse square)
    float constant;                 // RBL_FALLOFF_CLASSIC coefficients, >= 0 (all zero = 1, 0, 0: no falloff)
    float linear;
    float quadratic;
} RblLight;

// Fog; zero means none
typedef struct RblFog {
    int mode;                       // RblFogMode (0 = none)
    Color color;                    // Fog colour (sRGB)
    float start;                    // Linear: distance where fog begins
    float end;                      // Linear: distance where it is opaque (> start)
    float density;                  // Exp, exp2: density per world unit (>= 0)
} RblFog;

// Lighting settings shared by lit programs and G-buffers (a deferred variant takes its G-buffer's)
typedef struct RblShading {
    int brdf;                       // RblBrdf (0 = Lambert)
    int lightFeatures;              // RblLightFeature flags (0 = point lights, windowed falloff); see RblGetLightFeatures()
    int fog;                        // RblFogMode compiled in (0 = none); the scene's fog of that mode applies
    int tonemap;                    // RblTonemap (0 = none: clamp)
    float gamma;                    // Display encoding pow(c, 1/gamma), 1/16..16 (0 = the exact sRGB curve)
    bool linearOutput;              // Write linear light (float targets; clamped to 65504) instead of encoding
    int shadowMaps;                 // Scene shadow maps received (0 = none, at most RBL_MAX_SHADOWS)
    int shadowFilter;               // PCF footprint in texels per side, 1..RBL_SHADOW_MAX_FILTER (0 = 2): (n + 1)^2 fetches
} RblShading;

// Lit program request; zero means default. Only what changes the compiled code is here: per-material
// values (colours, specular, roughness, emission, alpha cutoff) travel with each draw's Material, and
// lights, ambient, fog, exposure and shadow maps with the frame's RblScene.
typedef struct RblLitShaderDesc {
    RblShading shading;             // How light is computed and written (the G-buffer's passes take the same struct)
    int maxLights;                  // Light slots compiled in (0 = 4, at most RBL_MAX_LIGHTS); the scene's first lights fill them
    RblMaterialLayout material;     // Maps the material provides (zero = albedo only; see RblPackMaterial)
    bool instanced;                 // Vertex stage for RblDrawInstanced() instead of vertex buffers
    bool deferred;                  // Geometry-pass variant: writes a G-buffer (RblBeginGBuffer) instead of lighting
    bool skinning;                  // Vertex stage skins GPU-skinned Models by their boneMatrices (RblDrawModel; needs RBL_GPU_SKINNING)
    bool softParticles;             // Fade alpha where the billboard meets the scene's depth (RblScene.depth; forward only)
    bool crossFade;                 // Mix a second atlas frame (RblBatchAddFade, RblDrawBillboardFade, RblInstancedDesc.fades): every map fetched twice
    int debugOutput;                // RblDebugOutput (0 = the lit colour)
    bool transmission;              // Light through thin cards from a light behind them, by the material's RBL_PARAM_TRANSMISSION (deferred: RblGBufferDesc.transmission)
    bool relief;                    // March material.height toward each light in tangent space: embossed detail shadows the sprite (deferred: RblGBufferDesc.relief)
    int reliefSteps;                // Relief samples per light, 1..RBL_MAX_RELIEF_STEPS (0 = 16)
    bool shadowTransmittance;       // Receivers read the maps' transmittance targets: blended casters' partial, coloured shadows (forward variants; deferred: RblGBufferDesc.shadowTransmittance)
    bool clustered;                 // Every light of the scene through the scene's light grid (GL 3.3, ES 3, WebGL2; ES 2 and GL 2.1 keep maxLights slots)
} RblLitShaderDesc;

// Material.params slots a lit program reads (every per-material value: MATERIAL VALUES in the doc block)
typedef enum {
    RBL_PARAM_ALPHA_CUTOFF = 0,     // Material.params index of the alpha cutoff
    RBL_PARAM_SPECULAR = 1,         // Material.params index of the Blinn-Phong specular intensity
    RBL_PARAM_SOFT_DISTANCE = 2,    // Material.params index of the soft-particle fade distance (world units; 0 = 0.5)
    RBL_PARAM_TRANSMISSION = 3      // Material.params index of the transmission share (transmission programs; 0 = none)
} RblMaterialParam;

// Deferred debug views (RblSetGBufferOutput)
typedef enum {
    RBL_GBUFFER_OUTPUT_LIT = 0,       // The lit, resolved image
    RBL_GBUFFER_OUTPUT_ALBEDO,        // Albedo (sRGB)
    RBL_GBUFFER_OUTPUT_NORMAL,        // World normal *0.5 + 0.5
    RBL_GBUFFER_OUTPUT_SPECULAR,      // Specular intensity / roughness
    RBL_GBUFFER_OUTPUT_OCCLUSION,     // Ambient occlusion
    RBL_GBUFFER_OUTPUT_DEPTH,         // Linear distance to the eye / scale
    RBL_GBUFFER_OUTPUT_POSITION,      // fract(reconstructed world position / scale)
    RBL_GBUFFER_OUTPUT_LIGHT_COUNT,   // Lights evaluated per pixel, heat map (scale = count shown white)
    RBL_GBUFFER_OUTPUT_COUNT
} RblGBufferOutput;

// G-buffer request; zero means default. Geometry variants (RblLitShaderDesc.deferred) must use its brdf.
typedef struct RblGBufferDesc {
    int width;                      // Size in pixels (0 = the render size)
    int height;
    RblShading shading;             // Lighting passes and resolve (its deferred variants: the same brdf)
    bool transmission;              // Light through thin cards (geometry variants with desc.transmission): + the thin target
    bool relief;                    // Relief self-shadow of the scene's first 8 lights (variants with desc.relief): + the thin target
    bool shadowTransmittance;       // Light passes read the maps' transmittance targets (blended casters' tint; needs shading.shadowMaps)
} RblGBufferDesc;

// Deferred G-buffer (RblLoadGBuffer): 10 bytes per pixel + depth + RGBA16F light accumulation
typedef struct RblGBuffer {
    int width;                      // Size in pixels
    int height;
    Texture2D albedo;               // RGBA8: sRGB albedo; alpha: bits 23..16 of the normal/material word (DEFERRED)
    Texture2D normal;               // RGBA8: bits 55..24 of the word
    Texture2D params;               // RG8: bits 15..0 (material fields; layout: the DEFERRED notes above)
    Texture2D accum;                // RGBA16F: emission, ambient and lights (linear); alpha: occlusion
    Texture2D depth;                // Depth texture (raylib's rlLoadTextureDepth: 24 or 32 bits, the driver's choice)
    Texture2D thin;                 // RGBA8, desc.transmission or desc.relief only: transmission share, relief bits (id 0 otherwise)
    RblGBufferDesc desc;            // Settings, defaults applied
    int output;                     // RblGBufferOutput shown by the resolve (RblSetGBufferOutput)
    float outputScale;              // Range of the depth/position/light-count outputs
#if defined(RBL_INSTRUMENTS)
    bool naiveFullscreen;           // Light every light in full-screen passes (the benchmarks' baseline)
#endif
    int lightsInVolumes;            // Last RblDrawDeferredLights: lights drawn as volumes
    int lightsFullscreen;           // ... and in full-screen passes
    unsigned int id;                // Object id: a stale copy is recognised by it (0 = not loaded)
    struct rbl__GBufferState *state; // The header's: framebuffers, pass programs, light volumes, camera (NULL = not loaded)
} RblGBuffer;

// Shadow map settings; zero means default (the biases are in shadow-map texels, see SHADOWS)
typedef struct RblShadowDesc {
    int size;                       // Texels per side, square (0 = 1024; 16..RBL_MAX_TARGET_SIZE)
    float constantBias;             // Depth bias (0 = 0.2; negative = none)
    float slopeBias;                // Depth bias per unit tan(incidence) (0 = 0.1; negative = none)
    float normalBias;               // Lookup offset along the receiver normal x sin(incidence) (0 = 0.25; negative = none)
    float minCastAngle;             // AXIS billboards tilt until the light sees them at >= this, degrees (0 = 30; negative = never)
    bool faceCamera;                // Billboards cast facing the billboard call's camera (default: facing the light; see SHADOWS)
    bool selfShadow;                // No caster identities: billboards may shadow themselves, no casters target (4 B/texel less)
    bool omni;                      // Point light: six cube faces, 3 x 2 tiles of size texels (RblShadowMapPasses: 6)
    int cascades;                   // Directional: 2..4 cascades fitted to a camera (RblFitShadowCascades), side by side (0 = one map)
    float cascadeLambda;            // Practical split: 0..1 from uniform to logarithmic (0 = 0.75; negative = 0)
    float cascadeBlend;             // Share of each cascade's depth range blended into the next (0 = 0.1; negative = none; <= 0.5)
    bool transmittance;             // RGBA8 transmittance target for blended casters (RblBeginShadowBlend; +4 B/texel; not on ES 2)
} RblShadowDesc;

// Shadow map of one light (directional, spot, or point with desc.omni): a depth texture and its light cameras (caster programs are the header's)
typedef struct RblShadowMap {
    Texture2D depth;                // Depth texture of the pass (receivers sample it only with desc.selfShadow); omni and cascades: every tile
    Texture2D casters;              // RGBA8: per texel the nearest caster's distance (16 bits) and identity (16 bits), what receivers sample (id 0 with desc.selfShadow)
    Texture2D transmittance;        // RGBA8: rgb the light blended casters let through (product), a the nearest one's distance (8 bits) (id 0 without desc.transmittance)
    int size;                       // Texels per side of one map (a cube face, a cascade)
    RblShadowDesc desc;             // Settings, defaults applied
    int light;                      // Scene light index of the last RblBeginShadowMap (-1 before the first)
    unsigned int id;                // Object id: a stale copy is recognised by it (0 = not loaded)
    struct rbl__ShadowMapState *state; // The header's: framebuffer, light camera and matrices, pass state (NULL = not loaded)
} RblShadowMap;

// What lights the frame, set once per frame with RblSetScene(); zero means default
typedef struct RblScene {
    const RblLight *lights;         // Lights (read and packed by RblSetScene; the array may change afterwards)
    int lightCount;                 // Forward programs light the first maxLights of them (clustered ones and the G-buffer every one)
    Color ambient;                  // Ambient colour (sRGB); the sky colour when ambientGround is given
    Color ambientGround;            // Hemispheric ground colour (all zero = ambient: flat)
    Vector3 ambientUp;              // Hemisphere up (zero = +Y)
    RblFog fog;                     // Fog parameters (mode 0 = none); programs compiled with RblShading.fog apply it
    float exposure;                 // Radiance scale before the tonemap (0 = 1)
    const RblShadowMap *shadowMaps;  // Maps rendered this frame for lights of this scene (RblBeginShadowMap)
    int shadowMapCount;             // At most RBL_MAX_SHADOWS
    Texture2D depth;                // Opaque scene depth for soft particles: RblLoadSceneTarget's .depth or a G-buffer's (id 0 = none)
} RblScene;

#if !defined(RBL_NO_ATLAS)
// Sprite-sheet atlas formats (RblLoadAtlasFromMemory; RblLoadAtlas detects by content)
typedef enum {
    RBL_ATLAS_AUTO = 0,             // Detect: JSON (Aseprite when meta.app names it, else TexturePacker) or libGDX text
    RBL_ATLAS_TEXTUREPACKER,        // TexturePacker JSON, hash or array form (multipack through RblLoadAtlas)
    RBL_ATLAS_ASEPRITE,             // Aseprite JSON, hash or array form: durations, frame tags, slices
    RBL_ATLAS_LIBGDX                // libGDX .atlas / .pack text, old (xy/size/orig/offset) or new (bounds/offsets) form
} RblAtlasFormat;

// Playback direction of a tag (Aseprite's names)
typedef enum {
    RBL_SPRITE_FORWARD = 0,         // from .. to
    RBL_SPRITE_REVERSE,             // to .. from
    RBL_SPRITE_PINGPONG,            // from .. to .. from (each leg is one pass; the turn frame shows once)
    RBL_SPRITE_PINGPONG_REVERSE     // to .. from .. to
} RblSpriteDirection;

// A frame's polygon mesh (TexturePacker polygon packing): the opaque part as triangles; read-only
typedef struct RblAtlasPolygon {
    int vertexCount;                // Vertices (3..65535)
    const Vector2 *vertices;        // Untrimmed-frame pixels, top-left origin, upright (the file's "vertices"; inside size)
    const Vector2 *uvs;             // Sheet texels of each vertex (the file's "verticesUV"; inside the frame's block)
    int indexCount;                 // Indices, 3 per triangle (the file's "triangles", winding as written)
    const unsigned short *indices;  // Vertex of each triangle corner (each < vertexCount), as raylib's Mesh.indices
} RblAtlasPolygon;

// One frame of an atlas, every format normalised to one convention (TexturePacker's)
typedef struct RblAtlasFrame {
    const char *name;               // Frame name (hash key, "filename", libGDX region name); owned by the atlas
    int page;                       // Sheet (RblAtlas.pages) the frame lies in
    Rectangle block;                // Texels it occupies in its sheet (stored turned: the h x w block)
    Rectangle source;               // As RblBillboard.source takes it with flags (libGDX's counter-clockwise turn: both extents negated)
    unsigned int flags;             // RBL_FRAME_ROTATED when stored turned (clockwise, after the conversion above); a polygon frame's RBL_FRAME_POLYGON bits
    Rectangle trim;                 // Drawn (trimmed) part of the frame: pixels, top-left origin, upright
    Vector2 size;                   // Untrimmed frame size in pixels
    Vector2 pivot;                  // Pivot as fractions of size from the top-left (none given: 0.5, 1, the bottom centre)
    float duration;                 // Seconds (Aseprite's milliseconds / 1000); 0 = none given
    int index;                      // libGDX animation index (-1 = none)
    Rectangle center;               // 9-slice centre in untrimmed-frame pixels (TexturePacker scale9Borders, libGDX split); zero = none
    const RblAtlasPolygon *polygon; // Polygon mesh (TexturePacker vertices/verticesUV/triangles); NULL = the trimmed quad
} RblAtlasFrame;

// A named run of frames (Aseprite frame tags; libGDX regions sharing a name with index >= 0)
typedef struct RblAtlasTag {
    const char *name;               // Tag name (owned by the atlas; names may repeat)
    int from, to;                   // First and last frame, inclusive (from <= to)
    int direction;                  // RblSpriteDirection
    int repeat;                     // Passes to play (0 = forever)
} RblAtlasTag;

// One sheet image
typedef struct RblAtlasPage {
    const char *image;              // Sheet path (RblLoadAtlas: the file found, see SPRITE SHEETS; from memory: as written)
    int width, height;              // Size the file states (0 = not stated)
    const char *normalImage;        // Same-layout normal sheet: the file's normalMap, else <image>_n.<ext> found beside it (RblLoadAtlas); NULL = none
    float scale;                    // Exporter scale (meta.scale, textures[].scale; 1 = none): frames are drawn at pixels / scale
    bool premultiplied;             // Texels hold colour x alpha (libGDX pma: true); RblLoadAtlasTextures reports it in the layout
} RblAtlasPage;

// One key of an Aseprite slice: applies from its frame until the slice's next key (a sub-frame a billboard can draw)
typedef struct RblAtlasSlice {
    const char *name;               // Slice name (owned by the atlas)
    int frame;                      // First frame the key applies to
    int lastFrame;                  // Last frame it applies to (before the slice's next key, or its sprite's last frame)
    Rectangle bounds;               // Untrimmed-canvas pixels, top-left origin
    Vector2 pivot;                  // Canvas pixels: bounds origin + the file's pivot (none given: the bounds' bottom centre)
    bool hasPivot;                  // The key gives a pivot (the one pivoted slice of an export also sets its frames' pivots)
    Rectangle center;               // 9-slice centre, canvas pixels (the key's center + bounds origin); zero = none
} RblAtlasSlice;

// A loaded atlas: one frame table every draw path reads (RblAtlasBillboard / RblAtlasInstance)
typedef struct RblAtlas {
    int format;                     // RblAtlasFormat it was read as
    int frameCount, tagCount, pageCount, sliceCount;
    const RblAtlasFrame *frames;    // The tables (owned by state; valid until RblUnloadAtlas)
    const RblAtlasTag *tags;
    const RblAtlasPage *pages;
    const RblAtlasSlice *slices;
    unsigned int id;                // Object id: a stale copy is recognised by it (0 = not loaded)
    struct rbl__AtlasState *state;  // The header's: tables and names (NULL = not loaded)
} RblAtlas;

// Animation playback: a plain value, advanced by RblUpdateSprite
typedef struct RblSpritePlayer {
    int tag;                        // Tag played (-1 = every frame of the atlas, forward, forever)
    int frame;                      // Frame shown now (index into the atlas frames)
    float time;                     // Seconds into the current frame
    int step;                       // +1 or -1: the way through the tag now (a pingpong turn flips it)
    int passes;                     // Passes completed (a pingpong leg is one pass)
    int loops;                      // Passes to play (0 = forever)
    bool finished;                  // The last pass ended: the frame stays on its last frame
} RblSpritePlayer;
#endif // RBL_NO_ATLAS

#if defined(__cplusplus)
extern "C" {            // Prevents name mangling of functions
#endif

//----------------------------------------------------------------------------------
// Module Functions Declaration   >>api
//----------------------------------------------------------------------------------
// Module lifetime (code: >>private, >>batch)
RBLAPI void RblClose(void);                                                   // End the module: free what the header owns (your objects stay yours; any order with your unloads and CloseWindow)
RBLAPI const char *RblGetFailureReason(void);                                // Why the last refused call failed: its log line without "RBL: " ("" before any; kept until the next refusal)

// Geometry (CPU, no GL needed; code: >>geometry)
RBLAPI RblCameraFrame RblGetCameraFrame(Camera3D camera);                                   // Camera frame with degenerate cases resolved
RBLAPI bool RblBillboardVertices(const RblCameraFrame *view, int textureWidth, int textureHeight, const RblBillboard *billboard, RblVertex out[4]); // Emit a quad (bottom-left, bottom-right, top-right, top-left); false = skipped, out untouched
RBLAPI int RblBillboardQuads(const RblCameraFrame *view, int textureWidth, int textureHeight, const RblBillboard *billboard, RblVertex *out, int capacity); // Emit what a batch draws: quads of 4 vertices (triangles 0-1-2, 0-2-3; last vertex repeated = one triangle), a polygon frame's triangle pairs; returns the quads (capacity short or out NULL: the count, nothing written); -1 = skipped

// Batched and immediate paths (GL; code: >>batch)
RBLAPI RblBatch RblLoadBatch(int capacity);                                   // Load a batch reserving capacity billboards (0 = default)
RBLAPI bool RblIsBatchValid(RblBatch batch);                                  // Check the batch owns its GPU buffers
RBLAPI void RblUnloadBatch(RblBatch *batch);                                  // Unload batch buffers
RBLAPI bool RblBeginBatch(RblBatch *batch, Camera3D camera);                  // Start collecting billboards seen by camera; false = rejected (billboards still pending, bad camera)
RBLAPI bool RblBatchAdd(RblBatch *batch, Material material, const RblBillboard *billboard); // Add one billboard; false = skipped (bad input)
RBLAPI int RblBatchAddMany(RblBatch *batch, Material material, const RblBillboard *billboards, int count); // Add count billboards of one material, as count RblBatchAdd calls would (the same skips and log line) at less cost a billboard; returns how many were not skipped
RBLAPI bool RblBatchAddFade(RblBatch *batch, Material material, const RblBillboard *billboard, const RblFade *fade); // Add one billboard cross-faded to a second frame (a crossFade program draws it); false = skipped (bad input)
RBLAPI void RblEndBatch(RblBatch *batch);                                     // Upload once (unless the adds wrote the mapped GPU buffer) and draw each material run
RBLAPI void RblDrawBillboard(Camera3D camera, Material material, RblBillboard billboard); // Draw one billboard now (immediate path)
RBLAPI void RblDrawBillboardFade(Camera3D camera, Material material, RblBillboard billboard, RblFade fade); // Draw one cross-faded billboard now (immediate path)

// Instanced path (GL): per-instance data only, quads expanded in the vertex shader (code: >>instanced)
RBLAPI RblInstanceBuffer RblLoadInstanceBuffer(int capacity);                 // Load an instance buffer (0 = default capacity)
RBLAPI bool RblIsInstanceBufferValid(RblInstanceBuffer buffer);               // Check the buffer owns its GPU objects
RBLAPI void RblUnloadInstanceBuffer(RblInstanceBuffer *buffer);               // Unload an instance buffer
RBLAPI int RblDrawInstanced(RblInstanceBuffer *buffer, Camera3D camera, Material material, RblInstancedDesc desc, const RblInstance *instances, int count); // Draw with one instanced call (material.shader: an instanced lit variant); returns instances drawn

// Material maps (CPU, no GL needed): packing, encodings, authoring help (code: >>maps)
RBLAPI bool RblPackMaterial(const RblMaterialSource *source, RblPackedMaterial *packed); // Pack an atlas's maps; false = invalid input (logged), packed untouched
RBLAPI void RblUnloadPackedMaterial(RblPackedMaterial *packed);               // Free packed Images
RBLAPI void RblEncodeNormal(Vector3 normal, int encoding, unsigned char out[3]); // Encode a unit tangent-space normal (RG used; RGB for RBL_NORMAL_RGB)
RBLAPI Vector3 RblDecodeNormal(const unsigned char in[3], int encoding);     // Decode as the shaders do (unit length, never NaN)
#if defined(RBL_INSTRUMENTS)
RBLAPI RblNormalErrorStats RblMeasureNormalEncoding(int encoding, const Vector3 *normals, int count); // Angular error of encode+decode over unit normals (RBL_INSTRUMENTS)
#endif
RBLAPI Image RblGenNormalMapFromHeight(Image height, float strength, bool wrap); // Tangent-space normal map (OpenGL convention) from a height map (grey)
RBLAPI Image RblGenHeightFromLuminance(Image albedo);                         // Height (grey) from albedo luminance, for RblGenNormalMapFromHeight
RBLAPI Image RblGenOcclusionFromHeight(Image height, int radius, float strength); // Cavity occlusion (grey) from a height map
RBLAPI bool RblLoadPackedTextures(const RblPackedMaterial *packed, Material *material); // Upload packed Images into material slots (GL): ALBEDO, NORMAL (material texture), EMISSION

// Lit programs (compiled features only) and the frame's scene (code: >>programs, >>scene)
RBLAPI Shader RblLoadLitShader(RblLitShaderDesc desc);                         // Lit program for Material.shader (equal descs share one program); id 0 + log on failure
RBLAPI bool RblIsLitShaderValid(Shader shader);                                // Check it is a live lit program of this header (not raylib's fallback, not unloaded)
RBLAPI void RblUnloadLitShader(Shader *shader);                                // Release this holder's reference and zero it (the program goes with its last holder)
RBLAPI int RblGetLightFeatures(const RblLight *lights, int count);               // RblLightFeature flags a light set needs (for RblShading.lightFeatures)
RBLAPI bool RblSetScene(const RblScene *scene);                                // Lights, ambient, fog, exposure and shadow maps for every lit program and G-buffer; false = rejected, previous scene kept
#if defined(RBL_INSTRUMENTS)
RBLAPI RblLightGridStats RblGetLightGridStats(void);                            // The scene's light grid as last built (RBL_INSTRUMENTS)
#endif
RBLAPI void RblDrawModel(Model model, Vector3 position, float scale, Color tint); // DrawModel with each material's lit values (colour, G-buffer or shadow pass)
RBLAPI void RblDrawMesh(Mesh mesh, Material material, Matrix transform);      // DrawMesh with the material's lit values (colour, G-buffer or shadow pass)

// Deferred G-buffer (code: >>deferred)
RBLAPI RblGBuffer RblLoadGBuffer(RblGBufferDesc desc);                         // Load a G-buffer and its lighting passes; invalid + log when MRT/float targets/shaders fail
RBLAPI RenderTexture2D RblLoadSceneTarget(int width, int height);                // Render texture with a depth texture (soft particles read it via RblScene.depth); UnloadRenderTexture frees it
RBLAPI bool RblBeginSceneDepth(void);                                          // Draw the opaque world into the header's scene target (its depth readable; follows the current target's size); false = refused
RBLAPI void RblEndSceneDepth(void);                                            // Show that world on the current target with its depth; soft particles read it (unless RblScene.depth is given)
RBLAPI bool RblIsGBufferValid(RblGBuffer gbuffer);                             // Check every target and pass loaded (false: render forward instead)
RBLAPI bool RblResizeGBuffer(RblGBuffer *gbuffer, int width, int height);    // Recreate the targets at a new size (passes kept); false = unchanged
RBLAPI void RblUnloadGBuffer(RblGBuffer *gbuffer);                           // Unload every GL object of the G-buffer and zero it
RBLAPI int RblGBufferBytesPerPixel(const RblGBuffer *gbuffer);               // Bytes per pixel of the colour targets, excluding depth and accumulation
RBLAPI bool RblBeginGBuffer(RblGBuffer *gbuffer, Camera3D camera);           // Start the geometry pass (draw with deferred variants of the G-buffer's brdf); false = rejected
RBLAPI void RblEndGBuffer(RblGBuffer *gbuffer);                              // End the geometry pass
RBLAPI bool RblDrawDeferredLights(RblGBuffer *gbuffer);                      // The scene's lights into the accumulation (bounded lights as volumes; the ambient: the resolve); false = rejected
RBLAPI void RblSetGBufferOutput(RblGBuffer *gbuffer, int view, float scale);   // Select a debug view (RblGBufferOutput) and its range
RBLAPI void RblResolveGBuffer(RblGBuffer *gbuffer);                          // The ambient (once per pixel), fog, tonemap and encode into the current target, writing the G-buffer depth

// Shadows (code: >>shadows)
RBLAPI RblShadowMap RblLoadShadowMap(RblShadowDesc desc);                     // Load a depth target (caster programs are the header's); invalid + log on failure
RBLAPI bool RblIsShadowMapValid(RblShadowMap map);                            // Check the target loaded
RBLAPI void RblUnloadShadowMap(RblShadowMap *map);                            // Unload the target and zero it
RBLAPI bool RblBeginShadowMap(RblShadowMap *map, const RblScene *scene, int lightIndex, Vector3 focusCenter, float focusRadius); // Shadow pass of scene->lights[lightIndex]: directional = orthographic over the focus sphere, spot = its cone (pass 0 of a map with more); false = rejected
RBLAPI void RblEndShadowMap(RblShadowMap *map);                               // End the shadow pass (restores target, viewport, matrices; culling on, depth test off)
RBLAPI int RblShadowMapPasses(RblShadowMap map);                              // Passes one frame of the map takes: 1, 6 (omni: a cube face each) or desc.cascades; 0 = invalid
RBLAPI bool RblBeginShadowMapPass(RblShadowMap *map, const RblScene *scene, int lightIndex, int pass, Vector3 focusCenter, float focusRadius); // Pass 0..RblShadowMapPasses-1 (a cube face, a cascade: its focus is the fit's); false = rejected
RBLAPI bool RblFitShadowCascades(RblShadowMap *map, Camera3D camera, float aspect, float nearDistance, float farDistance); // Cascaded map: split near..far (practical split) and fit each cascade to this camera, before its passes
RBLAPI void RblDrawShadowCascades(RblShadowMap map);                          // Debug view (inside BeginMode3D): each cascade's camera slice and light window in RblShadowCascadeColor(c)
RBLAPI Color RblShadowCascadeColor(int cascade);                              // Debug colour of cascade 0..3: red, green, blue, yellow (grey otherwise)
RBLAPI bool RblBeginShadowBlend(bool coloured);                                // Inside a shadow pass of a map with desc.transmittance: draws are blended casters (coverage; coloured: x their colour); false = rejected
RBLAPI void RblEndShadowBlend(void);                                           // Back to opaque casters (RblEndShadowMap ends it too)
RBLAPI bool RblShadowFocusFromCamera(Camera3D camera, float aspect, float nearDistance, float farDistance, Vector3 *center, float *radius); // Bounding sphere of a camera's frustum slice (a directional shadow's focus)

#if !defined(RBL_NO_ATLAS)
// Sprite-sheet atlases and animation (CPU, no GL needed; code: >>atlas)
RBLAPI RblAtlas RblLoadAtlas(const char *fileName);                          // Load an atlas file (format detected; TexturePacker multipacks follow related_multi_packs); invalid + log on failure
RBLAPI RblAtlas RblLoadAtlasFromMemory(const char *text, int size, int format); // Parse size bytes of atlas text (RblAtlasFormat, 0 = detect); invalid + log on failure
RBLAPI bool RblIsAtlasValid(RblAtlas atlas);                                  // Check it is a loaded atlas (not zero, not unloaded)
RBLAPI void RblUnloadAtlas(RblAtlas *atlas);                                  // Free the atlas's tables and zero it
RBLAPI int RblAtlasFindFrame(const RblAtlas *atlas, const char *name);        // First frame of that name; -1 when none
RBLAPI int RblAtlasFindTag(const RblAtlas *atlas, const char *name);          // First tag of that name; -1 when none
RBLAPI bool RblAtlasBillboard(const RblAtlas *atlas, int frame, float worldScale, RblBillboard *billboard); // Set source, size, origin and flags for a frame (world units per pixel); the rest kept
RBLAPI bool RblAtlasInstance(const RblAtlas *atlas, int frame, float worldScale, RblInstance *instance);   // The same for an instance
RBLAPI bool RblAtlasBillboardFade(const RblAtlas *atlas, int frame, int nextFrame, float weight, float worldScale, RblBillboard *billboard, RblFade *fade); // Cross-fade frame into nextFrame by weight 0..1: the quad covers both trims (each where its canvas and pivot put it), source, size, origin and flags set (the rest kept), fade filled for RblBatchAddFade / RblDrawBillboardFade
RBLAPI bool RblAtlasInstanceFade(const RblAtlas *atlas, int frame, int nextFrame, float weight, float worldScale, RblInstance *instance, RblFade *fade); // The same for an instance and its RblInstancedDesc.fades entry
RBLAPI int RblAtlasFindSlice(const RblAtlas *atlas, const char *name, int frame); // Key (RblAtlas.slices) of the named slice that applies at frame; -1 when none
RBLAPI bool RblAtlasSliceBillboard(const RblAtlas *atlas, int slice, int frame, float worldScale, RblBillboard *billboard); // Draw slice key slice of frame alone: source, size, origin, flags for its part of the trim about its own pivot; the rest kept
RBLAPI bool RblAtlasSliceInstance(const RblAtlas *atlas, int slice, int frame, float worldScale, RblInstance *instance); // The same for an instance
RBLAPI bool RblLoadAtlasTextures(const RblAtlas *atlas, int page, const char *normalSuffix, Material *material, RblMaterialLayout *layout); // Load a page's sheet into material maps[ALBEDO] and its same-layout normal sheet (page.normalImage, else <image><normalSuffix>.<ext>, NULL = "_n") into maps[NORMAL]; layout (NULL = none) gets RGB normals if found and pma; false + log: nothing changed
RBLAPI RblSpritePlayer RblPlaySprite(const RblAtlas *atlas, int tag, int loops); // Start a tag (-1 = all frames); loops: 0 = the tag's repeat, n > 0 = n passes, -1 = forever
RBLAPI bool RblUpdateSprite(RblSpritePlayer *player, const RblAtlas *atlas, float dt); // Advance by dt seconds honouring per-frame durations; false = rejected (player untouched)
RBLAPI int RblUpdateSpriteInstances(RblSpritePlayer *players, RblInstance *instances, int count, const RblAtlas *atlas, float dt, float worldScale); // Advance count players and set their instances' frame fields (checks once); returns how many (bad players skipped, one line)
RBLAPI float RblSpriteBlend(const RblSpritePlayer *player, const RblAtlas *atlas, int *nextFrame); // Cross-fade: the frame that follows and its weight 0..1 (time / duration); 0 and the same frame when finished
RBLAPI int RblSpriteViewSector(Vector3 viewDirection, float facingDegrees, int directions); // N-way sprites: sector 0..directions-1 the eye sees (0 = front; counter-clockwise seen from +Y); -1 + log on bad input

// Resident sprites of an atlas (GL 3.3 / ES 3 / WebGL2, as the instanced path; code: >>sprites)
RBLAPI RblSpriteBuffer RblLoadSpriteBuffer(const RblAtlas *atlas, int capacity); // Load resident sprites of an atlas (its frame table goes to the GPU); invalid + log on failure
RBLAPI bool RblIsSpriteBufferValid(RblSpriteBuffer buffer);                   // Check the buffer owns its GPU objects
RBLAPI void RblUnloadSpriteBuffer(RblSpriteBuffer *buffer);                   // Unload a sprite buffer and zero it
RBLAPI bool RblUpdateSprites(RblSpriteBuffer *buffer, int first, int count, const RblSpriteInstance *sprites); // Write sprites [first, first + count) (one upload); false + log: any bad sprite, nothing written
RBLAPI int RblDrawSpriteBuffer(RblSpriteBuffer *buffer, Camera3D camera, Material material, RblInstancedDesc desc, float time); // Draw the resident sprites the view can see at clock time (desc: no sort, no fades); returns sprites drawn
RBLAPI RblSpriteInstance RblMakeSprite(Vector3 position, float scale, float rotation, int frame, Color tint); // A static sprite (rotation in degrees, rounded to 360/65536)
RBLAPI bool RblAnimateSprite(RblSpriteInstance *sprite, int tag, int loops, float start, float speed); // Play tag (-1 = every frame) from clock start at speed; loops as RblPlaySprite (0 = the tag's repeat, -1 = forever, else 1..254)
#endif // RBL_NO_ATLAS

#if defined(__cplusplus)
}
#endif

#endif // RBILLBOARD_LIT_H

/***********************************************************************************
*
*   RBILLBOARD_LIT IMPLEMENTATION
*
************************************************************************************/
#if defined(RBILLBOARD_LIT_IMPLEMENTATION)

#include "rlgl.h"
#include <math.h>       // sqrtf, sinf, cosf, fabsf
#include <string.h>     // memcpy, memset, strlen
#include <stdio.h>      // snprintf, vsnprintf
#include <stdarg.h>     // va_list (atlas errors)
#include <stddef.h>     // offsetof
#include <stdlib.h>     // strtod, qsort, abs (atlas parsing)
// The batch's per-billboard steps, inlined into RblBatchAdd's loop body whatever the compiler's own limits
#if defined(__GNUC__) || defined(__clang__)
    #define RBL__FORCE_INLINE static inline __attribute__((always_inline))
#elif defined(_MSC_VER)
    #define RBL__FORCE_INLINE static __forceinline
#else
    #define RBL__FORCE_INLINE static inline
#endif
#if !defined(RBL_NO_SIMD) && (defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && (_M_IX86_FP >= 2)))
    #include <emmintrin.h>  // the batch's billboard checks and culling, four lanes at a time
    #define RBL__SSE2 1
#endif

#if defined(RBL_MALLOC) || defined(RBL_CALLOC) || defined(RBL_REALLOC) || defined(RBL_FREE)
    #if !defined(RBL_MALLOC) || !defined(RBL_CALLOC) || !defined(RBL_REALLOC) || !defined(RBL_FREE)
        #error "rbillboard_lit: define all of RBL_MALLOC, RBL_CALLOC, RBL_REALLOC and RBL_FREE, or none"
    #endif
#else
    #include <stdlib.h>
    #define RBL_MALLOC(sz)       malloc(sz)
    #define RBL_CALLOC(n,sz)     calloc(n,sz)
    #define RBL_REALLOC(ptr,sz)  realloc(ptr,sz)
    #define RBL_FREE(ptr)        free(ptr)
#endif

// Every header TraceLog goes through rbl__traceLog, which keeps the text of the last refusal
// (warnings starting "RBL: ") for RblGetFailureReason and hands the same line to raylib's TraceLog
static void rbl__traceLog(int level, const char *text, ...);
#define TraceLog(...) rbl__traceLog(__VA_ARGS__)

typedef char rbl__maxBonesInRange[((RBL_MAX_BONES >= 1) && (RBL_MAX_BONES <= 256))? 1 : -1];   // bone indices are bytes

// Material map slots raylib's DrawMesh binds (MAX_MATERIAL_MAPS of its default config)
#define RBL__RAYLIB_MATERIAL_MAPS 12
// GL entry points the header asks raylib's loader for (rlGetProcAddress): the platform's calling convention
#if defined(_WIN32)
    #define RBL__GLAPI __stdcall
#else
    #define RBL__GLAPI
#endif

// Quads per indexed draw: 16-bit indices (rlDrawVertexArrayElements) address 65536 vertices
#define RBL__QUADS_PER_CHUNK 16384

// Validation reads runs of floats: RblBillboard position .. source (rotation the 8th) and up ..
// roundness as words 0..20 (tint 12, facing 13), RblInstance position .. source; the batch's facing
// key reads facing .. axis as 7 words; a batch record reads size and origin as one vec4
typedef char rbl__billboardFloatRuns[((offsetof(RblBillboard, position) == 0) && (offsetof(RblBillboard, tint) == 12*4) && (offsetof(RblBillboard, facing) == 13*4) &&
                                      (offsetof(RblBillboard, up) == 14*4) && (offsetof(RblBillboard, axis) == 17*4) && (offsetof(RblBillboard, roundness) == 20*4) &&
                                      (offsetof(RblBillboard, source) + sizeof(Rectangle) - offsetof(RblBillboard, position) == 12*sizeof(float)) &&
                                      (offsetof(RblBillboard, rotation) - offsetof(RblBillboard, position) == 7*sizeof(float)) &&
                                      (offsetof(RblBillboard, origin) == offsetof(RblBillboard, size) + 2*sizeof(float)) &&
                                      (offsetof(RblBillboard, roundness) + sizeof(float) - offsetof(RblBillboard, up) == 7*sizeof(float)) &&
                                      (offsetof(RblInstance, tint) - offsetof(RblInstance, position) == 12*sizeof(float)))? 1 : -1];
// A resident sprite is 32 bytes, read by lit_instanced.vs.glsl as four attributes: pivot and scale
// (4 floats), start, tint, then rotation .. mode (4 unsigned shorts)
typedef char rbl__spriteLayout[((sizeof(RblSpriteInstance) == 32) && (offsetof(RblSpriteInstance, scale) == 12) && (offsetof(RblSpriteInstance, start) == 16) &&
                                (offsetof(RblSpriteInstance, tint) == 20) && (offsetof(RblSpriteInstance, rotation) == 24) && (offsetof(RblSpriteInstance, mode) == 30))? 1 : -1];

//----------------------------------------------------------------------------------
// Module Types and Structures Definition (private)   >>private
//----------------------------------------------------------------------------------
// Uniforms of every program the header compiles, looked up once per program into rbl__Program.loc
// (-1 where a variant has none): one location mechanism for forward, deferred and shadow passes
typedef enum {
    RBL__U_LIGHT_COUNT = 0, RBL__U_LIGHT_POSITION, RBL__U_LIGHT_COLOR, RBL__U_LIGHT_SPOT, RBL__U_LIGHT_ATTENUATION,
    RBL__U_AMBIENT, RBL__U_AMBIENT_GROUND, RBL__U_AMBIENT_UP, RBL__U_FOG, RBL__U_FOG_START, RBL__U_EXPOSURE,
    RBL__U_SHADOW_LIGHT, RBL__U_SHADOW_MATRIX, RBL__U_SHADOW_PARAMS, RBL__U_SHADOW_BIAS, RBL__U_SHADOW_AXES, RBL__U_SHADOW_TILES,
    RBL__U_ALPHA_CUTOFF, RBL__U_SPECULAR, RBL__U_ROUGH_METAL, RBL__U_EMISSIVE_COLOR, RBL__U_EMISSIVE_INTENSITY, RBL__U_INSTANCING,
    RBL__U_G_ALBEDO, RBL__U_G_NORMAL, RBL__U_G_PARAMS, RBL__U_G_DEPTH, RBL__U_G_ACCUM, RBL__U_INV_VIEW, RBL__U_EYE, RBL__U_MVP,
    RBL__U_OUTPUT, RBL__U_OUTPUT_SCALE, RBL__U_DEPTH_LINEAR, RBL__U_INV_P, RBL__U_VIEW_AXIS,
    RBL__U_SOFT_DEPTH, RBL__U_SOFT_TEXEL, RBL__U_CASTER_ID_ON, RBL__U_CASTER_DEPTH, RBL__U_FRAME_TABLE, RBL__U_TRANSMISSION, RBL__U_RELIEF, RBL__U_CASTER_TINT,
    RBL__U_G_THIN, RBL__U_RELIEF_INDEX, RBL__U_GRID_ORIGIN, RBL__U_GRID_DIMS, RBL__U_POLYGON, RBL__U_POLYGON_TABLE,
    RBL__U_COUNT
} rbl__Uniform;

typedef enum { RBL__KIND_LIT = 0, RBL__KIND_CASTER, RBL__KIND_PASS, RBL__KIND_COMPOSITE } rbl__ProgramKind;
#define RBL__MAX_CASCADES 4          // RblShadowDesc.cascades 2..4 (tiles in a row of one target)
enum { RBL__PASS_FULLSCREEN = 0, RBL__PASS_VOLUME, RBL__PASS_RESOLVE, RBL__PASS_FULLSCREEN_COUNT, RBL__PASS_VOLUME_COUNT, RBL__PASS_COUNT };

// What a program is compiled from: equal keys share one program
typedef struct rbl__ProgramKey {
    RblLitShaderDesc desc;          // Normalised (defaults applied, no padding garbage)
    int kind;                       // rbl__ProgramKind
    int pass;                       // G-buffer pass of a RBL__KIND_PASS program
    int sprites;                    // Header-owned variants: instanced bit 1 resident sprites (RBL_SPRITE_BUFFER), bit 2 polygon frames (RBL_POLYGONS); vertex-buffer bit 4 batch records (the instanced stage's RBL_BATCH_RECORD)
    int shadowKinds;                // Receivers: map k's compiled code in bits 4k..4k+3 (rbl__shadowCode; shadows.glsl)
    int gbufferRelief;              // 1: a G-buffer light pass reading the stored relief bits (RBL_GB_RELIEF)
} rbl__ProgramKey;

// Raw Material inputs of the per-draw values, kept to skip uploads when the next draw repeats them
typedef struct rbl__MaterialValues {
    Color specularColor, emissiveColor;
    float specular, shininess, roughness, metalness, emissive, alphaCutoff, alphaCeiling;
    float transmission, relief[4];  // transmission share; relief height (texels), 0, 1/width, 1/height of the material texture
} rbl__MaterialValues;

// One entry of the program registry
typedef struct rbl__Program {
    rbl__ProgramKey key;
    Shader shader;                       // Program and the registry's own raylib locs (every draw reads these, never a Material's)
    const int *handleLocs;               // Lit programs: the locs array handed out with it (compared, never read: raylib's UnloadShader frees it)
    int loc[RBL__U_COUNT];               // Uniform locations
    int refs;                            // Holders: 1 for a lit program (its handle); casters and passes: shadow maps, G-buffers
    rbl__MaterialValues values;          // Last per-draw values uploaded
    int fadeClipLoc;                     // Vertex-buffer crossFade programs: the rblFadeClip attribute (the linker's choice), else -1
    int casterIdLoc;                     // Vertex-buffer programs with caster identities: the rblCasterId attribute (the linker's choice), else -1
    bool valuesValid;
    bool raylibNoted;                    // raylib's DrawModel/DrawMesh was found to have drawn with it (said once)
    struct rbl__Program *spriteVariant;  // Instanced programs: the resident-sprite variant once compiled (goes with this one)
    struct rbl__Program *shadowBase;     // A receiver's variant for other map kinds: the program it was compiled for (goes with it), else NULL
    struct rbl__Program *shadowVariant;  // A receiver: its variant drawn last (a cache; the registry holds every variant)
    bool shadowVariantNoted;             // ... a variant failed to compile (said once)
    struct rbl__Program *polygonVariant; // Instanced programs: the polygon-frame variant (a sprite variant's: sprites and polygons)
    struct rbl__Program *recordVariant;  // Vertex-buffer programs: the batch-record variant once compiled (goes with this one)
} rbl__Program;

// A lit program handle that died (unloaded by the header or by raylib): its copies are recognised
// by the pair (stale Shader copies)
typedef struct rbl__DeadHandle {
    unsigned int id;
    const int *locs;
} rbl__DeadHandle;

// A billboard's place in a sorted batch
typedef struct rbl__SortKey {
    float depth;                    // Along the view axis (larger = farther)
    int index;                      // Billboard in submission order
    int run;                        // Its material run
} rbl__SortKey;

// A run of billboards sharing one material inside a batch
typedef struct rbl__BatchRun {
    Material material;               // Material the run draws with
    int first;                       // First billboard
    int count;                       // Billboards in the run
    int textureWidth, textureHeight; // Its albedo's size (rbl__albedoSize), read once per run
} rbl__BatchRun;

// A billboard's facing frame before its rotation, kept by a batch for the next billboard with the
// same facing and up (CAMERA_PLANE: the frame depends on nothing else).
typedef struct rbl__FrameCache {
    Vector3 key;                     // RblBillboard.up the frame was made for
    Vector3 right, up, normal;       // Unit frame
    Vector3 normalXRight, normalXUp; // Rotation helpers: normal x right, normal x up
    float upLength;                  // |caller up| (CAMERA_PLANE scales the height by it, as raylib)
    int facing;                      // Facing it was made for; -1 = empty
} rbl__FrameCache;

// A batched billboard in the batch's compact stream: where the context has GLSL 3 and the header's
// programs draw every run, the billboard itself instead of its four vertices; the vertex stage
// (lit_instanced.vs.glsl RBL_BATCH_RECORD) builds its frame and corners as the instanced path does
typedef RblBillboard rbl__BatchRecord;

// A batch's own data (RblBatch.state); capacity, count and skipped are mirrored into the RblBatch
typedef struct rbl__BatchState {
    RblVertex *vertices;            // 4 per billboard, or (records) an rbl__BatchRecord per billboard in the same memory
    RblVertex *sorted;              // Sorted copy of vertices (allocated at the first sorted RblEndBatch, grown with capacity)
    rbl__SortKey *keys;             // Per billboard: view depth, index, run (same lifetime as sorted)
    int sortCapacity;               // Billboards sorted and keys hold
    int capacity;                   // Billboards reserved (CPU and GPU)
    int count;                      // Billboards added since RblBeginBatch()
    rbl__BatchRun *runs;            // Material runs
    int runCount;                   // Runs used
    int runCapacity;                // Runs reserved
    int gpuCapacity;                // Billboards the GPU buffer holds
    unsigned int vaoId;             // Vertex array
    unsigned int vboId;             // Vertex buffer
    unsigned int eboId;             // Index buffer (quads share 16-bit indices in chunks)
    RblCameraFrame view;            // Frame of the current camera
    rbl__FrameCache frame;          // Facing frame of the last billboard (reused while facing and up repeat)
    int skipped;                    // Billboards skipped for bad input since RblBeginBatch()
    int culled;                     // Billboards accepted but outside the view since RblBeginBatch() (not in count)
    int planeCount;                 // Culling planes in use: 0 (off), 4 (a shadow pass's sides) or 6 (a camera's frustum)
    float cull[4][8];               // The planes by component (unit normal x, y, z and offset d: p is inside where n.p + d >= 0), padded to 8 with planes that keep everything
    // What a billboard's facing, up and axis give (rbl__facingKey), kept while they repeat
    unsigned int keyWords[7];       // The facing, up and axis bits the values below were made for
    bool keyValid;                  // keyWords holds a key (false from RblBeginBatch: the view changed)
    float keyHeightScale;           // CAMERA_PLANE with a caller up: its length (the height's scale, as raylib), else 1
    int backMode;                   // rbl__backMode of the up and axis as records hold them (tamed)
    Vector3 backNormal;
    bool orthographic;              // The camera's projection (which side of a quad it sees)
    bool backFacing;                // A billboard seen from behind was added: the draw turns culling off
    bool begun;                     // Between RblBeginBatch() and RblEndBatch()
    unsigned int pass;              // The pass it began in (rbl__passNow): added to and ended in that one only
    // The optional fade stream (16 floats per billboard: rbl__fadeVertices), allocated when the first
    // billboard with a fade weight arrives; a batch without one uploads and binds nothing more
    float *fade;                    // Per billboard since RblBeginBatch() while fading (capacity billboards)
    float *fadeSorted;              // Sorted copy (allocated at the first sorted fading RblEndBatch)
    int fadeSortCapacity;           // Billboards fadeSorted holds
    unsigned int fadeVboId;         // GPU copy (attribute location 5), created at the first fading RblEndBatch
    int fadeGpuCapacity;            // Billboards fadeVboId holds
    bool fading;                    // A billboard since RblBeginBatch() had a fade weight: fade[0..count) is filled
    // The optional caster identity stream (RBL__ID_BYTES per billboard: rbl__casterId as two bytes per
    // vertex), filled from the first billboard a shadow pass casts or a shadow receiver draws
    unsigned char *ids;             // Per billboard since RblBeginBatch() while identified (capacity billboards)
    unsigned char *idsSorted;       // Sorted copy (allocated at the first sorted identified RblEndBatch)
    int idSortCapacity;             // Billboards idsSorted holds
    unsigned int idVboId;           // GPU copy, created at the first identified RblEndBatch
    int idGpuCapacity;              // Billboards idVboId holds
    bool identified;                // ids[0..count) is filled (records: due, written if they turn to vertices)
    // Polygon frames (RBL_FRAME_POLYGON): a billboard takes one quad slot per pair of its triangles.
    // From the first such billboard, every slot's sort key (its billboard's quad centre) is kept
    float *centres;                 // 3 floats per slot while polygonal (capacity slots)
    bool polygonal;                 // centres[0..count) is filled
    int extraSlots;                 // Slots beyond one per billboard since RblBeginBatch() (count - extraSlots billboards)
    // The compact stream: from the first billboard, where GLSL 3 and the header's programs draw
    // every run, each billboard is a record; a billboard records cannot hold (a polygon, a fade, a
    // user's shader) turns the batch back to vertices (rbl__recordsToVertices)
    bool records;                   // vertices holds records [0, count)
    bool vertexOnly;                // Never records (the immediate path's one-quad batch)
    unsigned int recordVaoId;       // Vertex array of the record stream (instanced over the same buffer), made on first use
    // Records written straight into the GPU buffer: mapped from the first record to RblEndBatch where
    // the draw keeps submission order; a step that must read them on the CPU reads them back first
    rbl__BatchRecord *mapped;       // The mapped buffer while records are written there (NULL otherwise)
    bool onGpu;                     // Records [0, count) are only in the GPU buffer (rbl__recordsToCpu reads them back)
    bool mapOk;                     // This batch may map (set by RblBeginBatch)
    int mapRest;                    // Batches left that keep records on the CPU after one had to read mapped records back
} rbl__BatchState;

// An instance buffer's own data (RblInstanceBuffer.state)
typedef struct rbl__InstanceBufferState {
    RblInstance *staging;           // Compacted copy when a draw skips bad instances (clean sets upload directly)
    RblFade *fadeStaging;           // RblInstancedDesc.fades compacted [0, capacity) and sorted [capacity, 2 capacity) with the instances (first draw with fades)
    int fadeStagingCapacity;        // Instances fadeStaging serves (it holds twice as many fades)
    unsigned int fadeVboId;         // Second instance buffer (locations 15, 6, 7), created at the first draw with fades
    int fadeGpuCapacity;            // Fades fadeVboId holds
    RblInstance *sorted;            // Sorted copy (allocated at the first sorted draw, grown with capacity)
    rbl__SortKey *keys;             // Sort keys (same lifetime as sorted)
    int sortCapacity;               // Instances sorted and keys hold
    int capacity;                   // Instances reserved (CPU and GPU)
    unsigned int vaoId;             // Vertex array (instance attributes only)
    unsigned int vboId;             // Instance buffer
} rbl__InstanceBufferState;

// A G-buffer's own data (RblGBuffer.state)
typedef struct rbl__GBufferState {
    unsigned int id;                      // Geometry framebuffer: 4 colour attachments + depth texture
    unsigned int lightId;                 // Light framebuffer: the accumulation target alone
    unsigned int passes[RBL__PASS_COUNT]; // Lighting pass programs (the registry's)
    unsigned int volumeVao;               // Sphere proxy (vertex + index buffers) with per-light instance data
    unsigned int volumeVbo;
    unsigned int volumeIbo;
    unsigned int instanceVbo;
    unsigned int emptyVao;                // Full-screen triangle (positions from gl_VertexID)
    int volumeIndexCount;
    int instanceCapacity;                 // Lights the instance buffer holds (grows with a log line)
    Matrix view;                          // Camera of the last geometry pass
    Matrix projection;
    Vector3 eye;
    float ambient[9];                     // The scene's ambient (sky, ground, up) at the last RblBeginGBuffer (the resolve adds it)
    bool ambientNoted;                    // A later scene's other ambient was logged once
    bool geometryDone;                    // A geometry pass filled the targets (since load or the last resize)
    bool follow;                          // Loaded with size 0: takes its target's size at each RblBeginGBuffer
    bool sizeNoted;                       // A resolve into a target of another size was logged (until sizes match again)
    unsigned int savedFramebuffer;        // The caller's target at RblBeginGBuffer, restored by RblEndGBuffer
    bool begun;                           // Between RblBeginGBuffer() and RblEndGBuffer()
} rbl__GBufferState;

// A shadow map's own data (RblShadowMap.state)
#define RBL__SHADOW_SINGLE 0            // rbl__ShadowMapState.kind: one map (directional, spot)
#define RBL__SHADOW_OMNI 1              // six cube faces (point); 2..4: that many cascades
typedef struct rbl__ShadowMapState {
    unsigned int id;                      // Framebuffer (depth attachment only)
    int lightType;                        // RBL_LIGHT_DIRECTIONAL, RBL_LIGHT_SPOT or RBL_LIGHT_POINT (omni)
    int kind;                             // RBL__SHADOW_SINGLE, RBL__SHADOW_OMNI or the cascade count (2..4)
    int cols, rows;                       // Tiles of the targets: 1 x 1, 3 x 2 (cube faces), cascades x 1
    int pass;                             // Tile of the pass in progress or last run
    float tiles[4][4];                    // Receivers' per-tile data: omni [0] light position, half-width tan; cascades (1/width, -left/width, -bottom/width, far split)
    float cascadeRows[4][4];              // Cascades: world -> (x, y along right, up; window depth), camera view-depth plane
    double split[RBL__MAX_CASCADES + 1];  // Cascades: view-depth splits near..far (RblFitShadowCascades)
    double fitCenter[4][3], fitRadius[4]; // ... each cascade's bounding sphere (its slice, widened by the blend band below)
    double blend;                         // ... the blend band's share of a cascade's depth range
    bool fitted;                          // ... RblFitShadowCascades ran
    RblCameraFrame fitView;               // ... its camera frame, tan of half its vertical view (orthographic: half height), aspect
    double fitTan, fitAspect;
    bool fitOrthographic;
    RblCameraFrame lightView;             // Light camera frame (eye: spot position, or the directional camera's eye)
    Matrix view;                          // Light camera matrices of the last pass
    Matrix projection;
    Matrix matrix;                        // World -> (u, v, window depth) before the divide: view x projection x bias
    float texelWorld;                     // World size of a texel (perspective: per unit distance along the axis)
    float nearPlane;                      // Depth range along the light's axis
    float farPlane;
    Matrix savedView;                     // rlgl state restored by RblEndShadowMap: matrices and framebuffer
    Matrix savedProjection;
    unsigned int savedFramebuffer;
    unsigned int blendId;                 // Framebuffer of the transmittance target (and the same depth texture), 0 = none
    bool begun;                           // Between RblBeginShadowMap() and RblEndShadowMap()
    bool blending;                        // Between RblBeginShadowBlend() and RblEndShadowBlend()
    bool coloured;                        // ... and the blended casters tint by their colour
    Vector2 savedAlphaBand;               // rbl__state.alphaBand outside the blended casters
} rbl__ShadowMapState;

// What a shadow pass adds to billboard frames: AXIS billboards tilt until the light sees them at
// >= asin(minSin) (zero outside shadow passes)
typedef struct rbl__Cast {
    Vector4 light;                  // xyz toward the light (w 0) or its position (w 1)
    float minSin;
    bool faceLight;                 // Casters face the light (the pass's frame is the light's: orthographic for a directional light, so CAMERA_POSITION and AXIS face along it): AXIS tilts turn the front face to it
    bool radial;                    // An omni pass with light-facing casters: CAMERA_PLANE cards turn toward the light as CAMERA_POSITION ones (one frame for all six faces)
} rbl__Cast;

// The scene's light grid for clustered programs (light_grid.glsl): built from the packed lights at the
// first clustered program's upload after RblSetScene; storage grows to the largest scene
typedef struct rbl__LightGrid {
    float *data;                    // Light texture rows: RBL__GRID_DATA_LIGHTS lights x 4 RGBA32F texels
    float *list;                    // Grid texture: unbounded lights, cell starts (cells + 1), cell lists (R32F)
    int *counts;                    // Lights reaching each cell (build scratch)
    unsigned char *bounded;         // Per light: listed by cells (1) or lit everywhere (0) (build scratch)
    int dataCapacity;               // Allocated elements of data, list, counts and bounded
    int listCapacity;
    int countCapacity;
    int boundedCapacity;
    unsigned int dataId, listId;    // The textures (0 = none yet)
    int dataRows, listRows;         // Their allocated heights
    float origin[4];                // Corner of cell (0, 0, 0), 1/cell size (rblGridOrigin)
    int dims[4];                    // Cells along x, y, z; unbounded lights (rblGridDims)
    bool dirty;                     // The scene changed since the last build
    bool capNoted;                  // A capped cell was logged (again only after a scene without one)
    float cellSize;                 // What the last build made (RblGetLightGridStats)
    int entries, fullestCell, cappedCells, builds;
} rbl__LightGrid;

// The frame's scene, validated and packed once by RblSetScene
typedef struct rbl__Scene {
    float *lights;                             // RBL__LIGHT_FLOATS per light: position, colour, spot (vec4 each), falloff (vec3), shadow map + 1
    int *lightFeatures;                        // RblLightFeature bits each light needs
    float *staging;                            // Deferred volumes: bounded lights moved to the front
    int lightCount;
    int lightCapacity;
    float ambient[3], ground[3], up[3];
    float fog[4];                              // rgb linear colour, density or 1/(end - start)
    float fogStart;
    int fogMode;
    float exposure;
    int shadowCount;
    int shadowLight[RBL_MAX_SHADOWS];          // Scene light each map shadows
    unsigned int shadowId[RBL_MAX_SHADOWS];    // Each map's object id (an unload drops it from the scene)
    bool shadowDropped;                        // A map was unloaded after RblSetScene: its light draws unshadowed
    bool shadowDroppedNoted;                   // ... and a draw said so (once a scene)
    bool depthNoted;                           // The depth texture was found deleted at a draw (once a scene)
    unsigned int shadowTexture[RBL_MAX_SHADOWS];
    unsigned int shadowTint[RBL_MAX_SHADOWS];  // Each map's transmittance target (0 = none)
    float shadowUniforms[RBL_MAX_SHADOWS][48]; // Matrix rows, params, bias, axes, tiles as shadows.glsl reads them
    Texture2D depth;                           // Scene depth soft particles read (id 0 = none)
    rbl__LightGrid grid;                       // Clustered programs' lights
} rbl__Scene;

// The scene target of a plain raylib frame (RblBeginSceneDepth .. RblEndSceneDepth): the opaque world
// drawn where its depth is a texture, then shown on the caller's target with that depth
typedef struct rbl__SceneCapture {
    RenderTexture2D target;         // Follows the size of the target it is shown on (0 = not made yet)
    unsigned int composite;         // The composite program (registry, RBL__KIND_COMPOSITE)
    unsigned int vao, vbo;          // Full-screen triangle (vao 0 where the context has none)
    unsigned int savedFramebuffer;  // The caller's target at RblBeginSceneDepth
    bool begun;                     // Between RblBeginSceneDepth and RblEndSceneDepth
    bool shown;                     // RblEndSceneDepth ran: soft particles read its depth (RblScene.depth given: that one)
} rbl__SceneCapture;

// One slot of the loaded-object table (rbl__liveAdd)
typedef struct rbl__Live {
    unsigned int id;                // The object's id (0 = free slot)
    const void *state;              // Its private state
} rbl__Live;

// A polygon frame as the draw paths read it (an atlas's, registered under RBL_FRAME_POLYGON handles)
// The quad's two triangles meet on a diagonal of the frame, a = b or a + b = 1 in frame fractions
// (which one follows the mirrors and rotation: rbl__polygonDiagonal). Rounded normals and their
// tangents are affine over each of them (with a kink on the diagonal): a polygon is kept cut along
// each diagonal (cuts 0, 1), so every triangle lies in one of the quad's and takes its fields exactly,
// and as the file's triangles (cut 2) for flat billboards (constant normal and tangent: fewer, fatter
// triangles)
typedef struct rbl__Polygon {
    const Vector2 *frac;            // Vertices as fractions (a along +u, b along +v) of the frame's source: the file's, then the cut points
    const unsigned int *slots[3];   // Per cut, 4 vertices per slot drawn as a quad is: (0, 1, 2) and (0, 2, 3); a repeated last vertex = one triangle
    int slotCount[3];               // Slots (a batch draws each as one quad)
    int triangles[3];               // Triangles over all slots (the instanced stage's corners / 3)
} rbl__Polygon;

// Handles [first, first + count) of one atlas's polygons
typedef struct rbl__PolyRange {
    unsigned int first;
    int count;
    const rbl__Polygon *polygons;
} rbl__PolyRange;

// Everything the header keeps between calls (as rlgl's RLGL): zero-initialised, emptied by RblClose()
typedef struct rbl__State {
    rbl__Program **programs;           // The one program registry (each entry allocated: pointers stay valid as it grows)
    int programCount;
    int programCapacity;
    rbl__DeadHandle *dead;             // Lit handles that died, so their copies are refused (freed by RblClose)
    int deadCount;
    int deadCapacity;
    int **quarantine;                  // Locations arrays of handles RblUnloadLitShader released: kept allocated so no later
    int quarantineCount;               // allocation takes their address while a stale copy may hold it (freed by RblClose)
    int quarantineCapacity;
    void *glIs[3];                     // glIsProgram, glIsTexture, glIsVertexArray through raylib's loader (NULL: none)
    void *glGetUniformfv;              // ... and glGetUniformfv
    void *glMapBufferRange;            // ... glMapBufferRange and glUnmapBuffer (batch records; NULL: none, or not looked up yet)
    void *glUnmapBuffer;
    bool mapLooked;                    // Those two were looked up
    bool glLooked;
    bool closed;                       // RblClose ran: the tables go with the last object the caller holds
    rbl__SceneCapture capture;         // RblBeginSceneDepth/RblEndSceneDepth: the header's scene target
    rbl__Scene scene;
    RblBatch immediate;                // The immediate path's one-quad batch
    RblShadowMap *shadowPass;          // Shadow pass in progress (RblBeginShadowMap .. RblEndShadowMap): &shadowPassMap, or NULL
    RblShadowMap shadowPassMap;        // ... the map as it began (the caller's struct is never held)
    rbl__Cast cast;                    // ... and its light, for AXIS tilts
    RblGBuffer *gbufferPass;           // Geometry pass in progress (RblBeginGBuffer .. RblEndGBuffer): &gbufferPassBuffer, or NULL
    RblGBuffer gbufferPassBuffer;      // ... the G-buffer as it began
    Vector2 alphaBand;                 // A hybrid batch pass: x alpha cutoff (0 = the material's), y ceiling (0 = none)
    unsigned int casterIds[7];         // Caster programs (vertex buffers, instanced; skinned, cross-fade vertex buffers and instanced, blended vertex buffers and instanced: compiled on first use)
#if defined(RBL_INSTRUMENTS)
    bool gbufferForceFailure;          // Test hook: pretend MRT / float targets are unavailable
    bool gbufferFourDrawBuffers;       // Test hook: pretend GL_MAX_DRAW_BUFFERS is 4 (ES 3 / WebGL2's minimum)
    bool gbufferDriverDepth;           // Test hook: keep rlLoadTextureDepth's depth format (no float depth)
    long long stretchFours;            // Tests' count: fours RblBatchAddMany took four lanes at a time
    long long stretchSingles;          // ... and billboards its stretches took one at a time
    bool instanceNoMap;                // Test hook: RblDrawInstanced checks, then uploads (never maps)
    bool spriteNoMap;                  // Test hook: RblUpdateSprites uploads the caller's array (never maps)
    long long spriteMapped;            // Tests' count: RblUpdateSprites calls that wrote the mapped store
#endif
    char problem[512];                 // Why the last internal step failed (its public caller logs it once)
    char failure[512];                 // The last refusal line without "RBL: " (RblGetFailureReason)
    Matrix boneScratch[RBL_MAX_BONES]; // Bone matrices transposed for ES uploads (rbl__uploadBones)
    rbl__Live *live;                   // Loaded batches, instance buffers, G-buffers and shadow maps by slot (id 0: free)
    int liveCount;                     // Slots used (free ones are reused)
    int liveCapacity;
    rbl__PolyRange *polyRanges;        // Polygon handles of the loaded atlases, by first handle
    int polyRangeCount;
    int polyRangeCapacity;
    unsigned int polyNext;             // Next handle handed out (handles of an unloaded atlas are reused only once 2^20 - 1 ran out)
    unsigned int polyVersion;          // Changes with every range added or removed (the GPU table follows it)
    unsigned int polyTableId;          // The instanced stage's polygon table (RGBA32F), built at the first draw that needs it
    unsigned int polyTableVersion;     // polyVersion it was built at
    unsigned int polyTableBase;        // Lowest handle it holds
    int polyTableMaxCorners;           // Most corners (3 per triangle) of one polygon in it
} rbl__State;

static rbl__State rbl__state;
static void rbl__freeLightGrid(rbl__LightGrid *g);
static void rbl__bindLightGrid(void);
#if defined(RBL_INSTRUMENTS)
    #define RBL__HOOK(name) (rbl__state.name)
#else
    #define RBL__HOOK(name) false
#endif

static void rbl__traceLog(int level, const char *text, ...)
{
    char line[sizeof(rbl__state.failure) + 5];
    va_list args;
    va_start(args, text);
    vsnprintf(line, sizeof(line), text, args);
    va_end(args);
    const bool ours = (strncmp(line, "RBL: ", 5) == 0);
    if (ours && (level >= LOG_WARNING)) memcpy(rbl__state.failure, line + 5, strlen(line + 5) + 1);
    if (ours) (TraceLog)(level, "RBL: %s", line + 5);       // a log callback still sees the format start with "RBL: "
    else (TraceLog)(level, "%s", line);
}

const char *RblGetFailureReason(void) { return rbl__state.failure; }

// The GLSL dialect of rlgl's context (shaders/dialect.glsl): 330 desktop GL 3.3/4.3, 300 ES 3 and
// WebGL2, 120 GL 2.1, 100 ES 2 and WebGL1; 0 for a context this header cannot shade (GL 1.1, software)
static int rbl__glsl(void)
{
    switch (rlGetVersion())
    {
        case RL_OPENGL_33: case RL_OPENGL_43: return 330;
        case RL_OPENGL_ES_30: return 300;
        case RL_OPENGL_21: return 120;
        case RL_OPENGL_ES_20: return 100;
        default: return 0;
    }
}

// Names the context for log lines
static const char *rbl__contextName(void)
{
    switch (rbl__glsl())
    {
        case 330: return "OpenGL 3.3";
        case 300: return "OpenGL ES 3";
        case 120: return "OpenGL 2.1";
        case 100: return "OpenGL ES 2";
        default: return "OpenGL 1.1/software";
    }
}

// Instanced draws, the G-buffer and its passes need GLSL 3 (integer bits, MRT, instancing): NULL when
// the context has them, else the reason
static const char *rbl__needsGlsl3(const char *feature)
{
    if (rbl__glsl() >= 300) return NULL;
    snprintf(rbl__state.problem, sizeof(rbl__state.problem), "%s need OpenGL 3.3 or ES 3 (WebGL2); this context is %s: use the forward path", feature, rbl__contextName());
    return rbl__state.problem;
}

// Objects handed out (batches, instance buffers, G-buffers, shadow maps) are named by id: slot + 1 in
// the low 16 bits, a serial above. A stale copy (its object unloaded, its slot or its state's
// address perhaps taken by another since) carries an id no live object has, so it is recognised
// without dereferencing anything it holds. The serial outlives RblClose: no id repeats across it.
static unsigned int rbl__serial = 0;

// Whether GL may be called: raylib's window is open, or the header never saw one (a context made
// another way, e.g. rlglInit on a headless context). After CloseWindow the context is gone: unloads
// and RblClose then free memory only (both survive RblClose, as the serial)
static bool rbl__sawWindow = false;
static bool rbl__glUsable(void)
{
    if (IsWindowReady()) { rbl__sawWindow = true; return true; }
    return !rbl__sawWindow;
}

// Registers a loaded object's state; its id, or 0 when out of memory or slots
static unsigned int rbl__liveAdd(const void *state)
{
    int slot = -1;
    for (int i = 0; (i < rbl__state.liveCount) && (slot < 0); i++) if (rbl__state.live[i].id == 0) slot = i;
    if (slot < 0)
    {
        if (rbl__state.liveCount >= 0xFFFF) return 0;
        if (rbl__state.liveCount == rbl__state.liveCapacity)
        {
            int capacity = (rbl__state.liveCapacity > 0)? rbl__state.liveCapacity*2 : 16;
            rbl__Live *live = (rbl__Live *)RBL_REALLOC(rbl__state.live, (size_t)capacity*sizeof(rbl__Live));
            if (live == NULL) return 0;
            rbl__state.live = live;
            rbl__state.liveCapacity = capacity;
        }
        slot = rbl__state.liveCount++;
    }
    rbl__serial = (rbl__serial + 1u) & 0xFFFFu;
    if (rbl__serial == 0u) rbl__serial = 1u;
    rbl__state.closed = false;      // used again after RblClose
    rbl__state.live[slot].id = (rbl__serial << 16) | (unsigned int)(slot + 1);
    rbl__state.live[slot].state = state;
    return rbl__state.live[slot].id;
}

// The slot id names, or -1 (id 0 and ids of empty or reused slots included)
static inline int rbl__liveSlot(unsigned int id)
{
    unsigned int slot = (id & 0xFFFFu) - 1u;
    return ((id != 0u) && (slot < (unsigned int)rbl__state.liveCount) && (rbl__state.live[slot].id == id))? (int)slot : -1;
}

static void rbl__liveRemove(unsigned int id)
{
    int slot = rbl__liveSlot(id);
    if (slot >= 0) { rbl__state.live[slot].id = 0; rbl__state.live[slot].state = NULL; }
}

// Whether (id, state) is a loaded object: the id first, then its state pointer compared (not read)
static inline bool rbl__isLive(unsigned int id, const void *state)
{
    int slot = rbl__liveSlot(id);
    return (slot >= 0) && (state != NULL) && (rbl__state.live[slot].state == state);
}

// An unload's holder check: true when holder's object is live; otherwise one line under fn (NULL
// holder, zero holder, stale copy) and false
static void rbl__tidyAfterClose(void);

static bool rbl__unloadable(const void *holder, unsigned int id, const void *state, const char *fn, const char *what)
{
    if (holder == NULL) { TraceLog(LOG_WARNING, "RBL: %s: NULL %s", fn, what); return false; }
    if (rbl__isLive(id, state)) return true;
    TraceLog(LOG_WARNING, "RBL: %s: %s %s", fn, what, ((id != 0) || (state != NULL))? "already unloaded (a stale copy)" : "not loaded (zero, or unloaded before)");
    return false;
}

//----------------------------------------------------------------------------------
// Embedded shaders (generated from the .glsl files in shaders/ by `make shaders`; do not edit by hand)   >>shaders
//----------------------------------------------------------------------------------
// RBL-SHADERS-BEGIN
static const char *const rbl__shader_ambient[] = {
    "// Ambient: the scene's sky/ground light on a surface. Forward shaders add it per fragment; the\n",
    "// deferred resolve once per pixel, on the stored surface (occlusion from the accumulation's alpha).\n",
    "//   RBL_BRDF b                2 (GGX) adds the specular reflectance of a uniform environment\n",
    "#include \"surface.glsl\"\n",
    "\n",
    "uniform vec3 rblAmbient;                    // linear sky colour (the scene's ambient)\n",
    "uniform vec3 rblAmbientGround;              // linear ground colour (= rblAmbient for a flat ambient)\n",
    "uniform vec3 rblAmbientUp;                  // unit\n",
    "\n",
    "// Ambient: uniform light from every direction, attenuated by occlusion. GGX adds F0 times it (the\n",
    "// specular reflectance of a uniform environment, without a split-sum table).\n",
    "vec3 rblAmbientLight(RblShadingPoint s)\n",
    "{\n",
    "    vec3 ambient = mix(rblAmbientGround, rblAmbient, dot(s.normal, rblAmbientUp)*0.5 + 0.5);\n",
    "#if RBL_BRDF == 2\n",
    "    vec3 reflectance = s.albedo*(1.0 - s.metalness) + mix(vec3(0.04), s.albedo, s.metalness);\n",
    "#else\n",
    "    vec3 reflectance = s.albedo;\n",
    "#endif\n",
    "    return ambient*s.occlusion*reflectance;\n",
    "}\n",
    NULL };
static const char *const rbl__shader_common[] = {
    "// Common: constants and helpers every stage shares (the one sRGB transfer pair, safe normalise).\n",
    "// Included first by every stage (after dialect.glsl, its one include).\n",
    "#include \"dialect.glsl\"\n",
    "\n",
    "#define RBL_PI 3.14159265358979\n",
    "#define RBL_HALF_MAX 65504.0        // radiance clamp: a half-float target never receives Inf\n",
    "#define RBL_MIN_ROUGHNESS 0.045     // perceptual; alpha = 0.045^2 keeps D finite in fp32 (Filament's limit)\n",
    "\n",
    "// Upper-left 3x3 (GLSL ES 1.00 has no mat3(mat4) constructor)\n",
    "mat3 rblMat3(mat4 m)\n",
    "{\n",
    "    return mat3(m[0].xyz, m[1].xyz, m[2].xyz);\n",
    "}\n",
    "\n",
    "// normalize() of a zero vector is undefined (NaN on most GPUs): fall back instead.\n",
    "vec3 rblSafeNormalize(vec3 v, vec3 fallback)\n",
    "{\n",
    "    float len2 = dot(v, v);\n",
    "    return (len2 > 1e-20)? v*inversesqrt(len2) : fallback;\n",
    "}\n",
    "\n",
    "// The viewer of a shaded point: eye = camera position; axis.xyz = unit camera back direction (target\n",
    "// toward eye), axis.w = 1 for an orthographic projection (else 0). A parallel projection has no eye\n",
    "// point: every ray runs along the axis, so the view vector is the axis itself everywhere.\n",
    "vec3 rblViewVector(vec3 eye, vec4 axis, vec3 position, vec3 fallback)\n",
    "{\n",
    "    return (axis.w > 0.5)? axis.xyz : rblSafeNormalize(eye - position, fallback);\n",
    "}\n",
    "\n",
    "// Fog distance: to the eye (perspective); orthographic, along the view axis from the camera's plane\n",
    "float rblViewDistance(vec3 eye, vec4 axis, vec3 position)\n",
    "{\n",
    "    return (axis.w > 0.5)? max(dot(eye - position, axis.xyz), 0.0) : length(position - eye);\n",
    "}\n",
    "\n",
    "// Exact sRGB transfer functions (IEC 61966-2-1). Every raylib Color, albedo and emissive texel is\n",
    "// sRGB; lighting runs in linear light.\n",
    "vec3 rblSrgbToLinear(vec3 c)\n",
    "{\n",
    "    return mix(c/12.92, pow((c + 0.055)/1.055, vec3(2.4)), step(vec3(0.04045), c));\n",
    "}\n",
    "\n",
    "vec3 rblLinearToSrgb(vec3 c)\n",
    "{\n",
    "    c = clamp(c, 0.0, 1.0);\n",
    "    return mix(c*12.92, 1.055*pow(c, vec3(1.0/2.4)) - 0.055, step(vec3(0.0031308), c));\n",
    "}\n",
    NULL };
static const char *const rbl__shader_deferred_fullscreen_fs[] = {
    "// Deferred full-screen light pass, fragment stage: up to RBL_LIGHTS unbounded lights (directional,\n",
    "// range 0), added into the accumulation target's rgb (alpha 0 keeps the occlusion there).\n",
    "//   RBL_COUNT_LIGHTS    add the number of lights evaluated instead of light (heat-map view)\n",
    "#include \"gbuffer_read.glsl\"\n",
    "#include \"lights.glsl\"\n",
    "\n",
    "RBL_VARYING vec2 fragUv;\n",
    "out vec4 finalColor;\n",
    "\n",
    "void main()\n",
    "{\n",
    "    ivec2 texel;\n",
    "    float depth;\n",
    "    if (!rblLightPassTexel(texel, depth)) discard;\n",
    "#ifdef RBL_COUNT_LIGHTS\n",
    "    finalColor = vec4(vec3(float(rblLightCount)), 0.0);\n",
    "#else\n",
    "    RblShadingPoint s = rblGBufferSurface(texel, rblPositionFromDepth(texel, depth));\n",
    "    finalColor = vec4(rblDirectLight(s, rblViewVector(rblEye, rblViewAxis, s.position, s.normal)), 0.0);\n",
    "#endif\n",
    "}\n",
    NULL };
static const char *const rbl__shader_deferred_resolve_fs[] = {
    "// Deferred resolve, fragment stage: the scene's ambient on the stored surface (once per pixel, the\n",
    "// occlusion from the accumulation's alpha) plus the accumulated emission and light, through fog,\n",
    "// exposure, tonemap and the display encoding (output.glsl), writing the G-buffer's depth for later\n",
    "// forward draws; debug views.\n",
    "#include \"gbuffer_read.glsl\"\n",
    "#include \"ambient.glsl\"\n",
    "#include \"output.glsl\"\n",
    "\n",
    "RBL_VARYING vec2 fragUv;\n",
    "uniform int rblOutput;               // RblGBufferOutput\n",
    "uniform float rblOutputScale;            // linear depth / position / light count range of the debug views\n",
    "out vec4 finalColor;\n",
    "\n",
    "// Heat map for the light count view: black -> blue -> green -> yellow -> red -> white\n",
    "vec3 rblHeat(float t)\n",
    "{\n",
    "    t = clamp(t, 0.0, 1.0)*5.0;\n",
    "    vec3 c0 = vec3(0.0), c1 = vec3(0.0, 0.2, 1.0), c2 = vec3(0.0, 0.9, 0.3), c3 = vec3(1.0, 0.9, 0.0), c4 = vec3(1.0, 0.1, 0.0), c5 = vec3(1.0);\n",
    "    if (t < 1.0) return mix(c0, c1, t);\n",
    "    if (t < 2.0) return mix(c1, c2, t - 1.0);\n",
    "    if (t < 3.0) return mix(c2, c3, t - 2.0);\n",
    "    if (t < 4.0) return mix(c3, c4, t - 3.0);\n",
    "    return mix(c4, c5, t - 4.0);\n",
    "}\n",
    "\n",
    "void main()\n",
    "{\n",
    "    // The resolve covers the target with fragUv 0..1 (same size as the G-buffer expected; nearest texel otherwise)\n",
    "    ivec2 texel = ivec2(min(fragUv*vec2(textureSize(rblGDepth, 0)), vec2(textureSize(rblGDepth, 0) - 1)));\n",
    "    float depth = texelFetch(rblGDepth, texel, 0).r;\n",
    "    if (depth >= 1.0) discard;                          // background: nothing was drawn here\n",
    "    vec3 position = rblPositionFromDepth(texel, depth);\n",
    "    gl_FragDepth = depth;                               // later forward draws sort against this\n",
    "    vec4 accum = texelFetch(rblGAccum, texel, 0);\n",
    "    vec3 color = accum.rgb;\n",
    "    float viewDistance = rblViewDistance(rblEye, rblViewAxis, position);\n",
    "    RblShadingPoint s = rblGBufferSurface(texel, position);\n",
    "    if (rblOutput == 0)\n",
    "    {\n",
    "        s.occlusion = accum.a;\n",
    "        finalColor = vec4(rblFinish(color + rblAmbientLight(s), viewDistance), 1.0);\n",
    "        return;\n",
    "    }\n",
    "    vec3 v = vec3(0.0);\n",
    "    if (rblOutput == 1) v = rblLinearToSrgb(s.albedo);\n",
    "    else if (rblOutput == 2) v = s.normal*0.5 + 0.5;\n",
    "    else if (rblOutput == 3) v = vec3(s.specular);     // the stored channel: intensity or roughness\n",
    "    else if (rblOutput == 4) v = vec3(accum.a);          // kept by the geometry pass for this view\n",
    "    else if (rblOutput == 5) v = vec3(clamp(viewDistance/rblOutputScale, 0.0, 1.0));\n",
    "    else if (rblOutput == 6) v = fract(position/rblOutputScale);\n",
    "    else if (rblOutput == 7) v = rblHeat(color.r/rblOutputScale);\n",
    "    finalColor = vec4(v, 1.0);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_deferred_volume_fs[] = {
    "// Deferred light volume pass, fragment stage: one bounded light per instance, added into the\n",
    "// accumulation target; pixels outside the light's range are rejected from depth alone.\n",
    "//   RBL_COUNT_LIGHTS    add 1 per light evaluated instead of light (heat-map view)\n",
    "#include \"gbuffer_read.glsl\"\n",
    "#include \"lights.glsl\"\n",
    "\n",
    "RBL_FLAT RBL_VARYING vec4 volumePosition;\n",
    "RBL_FLAT RBL_VARYING vec4 volumeColor;\n",
    "RBL_FLAT RBL_VARYING vec4 volumeSpot;\n",
    "RBL_FLAT RBL_VARYING vec4 volumeFalloff;             // xyz attenuation, w code: shadow map index + 1 (0 = none) + 8 x (relief bit + 1)\n",
    "out vec4 finalColor;\n",
    "\n",
    "void main()\n",
    "{\n",
    "    ivec2 texel;\n",
    "    float depth;\n",
    "    if (!rblLightPassTexel(texel, depth)) discard;\n",
    "    vec3 position = rblPositionFromDepth(texel, depth);\n",
    "    // Most of a proxy's pixels lie outside the light's range\n",
    "    vec3 toLight = volumePosition.xyz - position;\n",
    "    if (dot(toLight, toLight)*volumeColor.a*volumeColor.a >= 1.0) discard;\n",
    "#ifdef RBL_COUNT_LIGHTS\n",
    "    finalColor = vec4(1.0, 1.0, 1.0, 0.0);     // alpha 0: the accumulation target's alpha keeps the occlusion\n",
    "#else\n",
    "    RblShadingPoint s = rblGBufferSurface(texel, position);\n",
    "    vec3 v = rblViewVector(rblEye, rblViewAxis, s.position, s.normal);\n",
    "    int code = int(volumeFalloff.w + 0.5);\n",
    "#ifdef RBL_GB_RELIEF\n",
    "    rblGbReliefLight = code/8 - 1;\n",
    "#endif\n",
    "#if RBL_SHADOWS > 0\n",
    "    int map = code - 8*(code/8) - 1;\n",
    "    vec3 l = rblSafeNormalize(volumePosition.xyz - s.position, s.normal);\n",
    "    float NdotL = dot(s.normal, l);\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    if (s.transmission > 0.0) NdotL = 1.0;          // the light behind the card is shadowed on its way too\n",
    "#endif\n",
    "    float shadow = ((map >= 0) && (NdotL > 0.0))? rblShadowAt(map, s, l) : 1.0;\n",
    "#else\n",
    "    float shadow = 1.0;\n",
    "#endif\n",
    "    vec3 light = rblEvalLight(s, v, volumePosition, volumeColor, volumeSpot, volumeFalloff.xyz, shadow);\n",
    "#if (RBL_SHADOWS > 0) && defined(RBL_SHADOW_TINT)\n",
    "    if (map >= 0) light *= rblShadowTint(map, s.position);\n",
    "#endif\n",
    "    finalColor = vec4(light, 0.0);\n",
    "#endif\n",
    "}\n",
    NULL };
static const char *const rbl__shader_dialect[] = {
    "// Dialect: the few words that differ between GLSL 330 (desktop GL 3.3+), GLSL ES 3.00 (ES 3, WebGL2),\n",
    "// GLSL 1.20 (GL 2.1) and GLSL ES 1.00 (ES 2, WebGL1). The loader writes the #version line and\n",
    "// RBL_GLSL (330, 300, 120 or 100), RBL_GLSL_ES on ES, and RBL_VERTEX_STAGE or RBL_FRAGMENT_STAGE\n",
    "// before any source; every other file writes these words instead. Included first (by common.glsl,\n",
    "// fullscreen.vs.glsl and volume.vs.glsl); includes nothing.\n",
    "//   RBL_ATTRIBUTE          a vertex input\n",
    "//   RBL_VARYING            a vertex output / fragment input\n",
    "//   RBL_FLAT               not interpolated (1.x dialects have no flat: such values are constant anyway)\n",
    "//   rblFetch(map, at, n)   texel `at` (ivec2) of an n x n texture, unfiltered\n",
    "//   RBL_DERIVATIVES        dFdx/dFdy exist in this fragment stage (GLSL ES 1.00: OES_standard_derivatives)\n",
    "// Instanced and deferred stages use GLSL 3 features (integer bits, MRT, layout locations): the loader\n",
    "// compiles them only for 330 and 300 es.\n",
    "\n",
    "#if defined(RBL_GLSL_ES) && (RBL_GLSL < 300) && defined(RBL_FRAGMENT_STAGE) && defined(GL_OES_standard_derivatives)\n",
    "#extension GL_OES_standard_derivatives : enable\n",
    "#endif\n",
    "#if defined(RBL_FRAGMENT_STAGE) && ((RBL_GLSL >= 300) || !defined(RBL_GLSL_ES) || defined(GL_OES_standard_derivatives))\n",
    "#define RBL_DERIVATIVES\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_GLSL_ES\n",
    "// Highp everywhere it exists: ES defaults samplers to lowp, which bands depth reads, and ES 2 may\n",
    "// lack highp in the fragment stage (then mediump, the most it has)\n",
    "#if (RBL_GLSL < 300) && defined(RBL_FRAGMENT_STAGE) && !defined(GL_FRAGMENT_PRECISION_HIGH)\n",
    "precision mediump float;\n",
    "precision mediump int;\n",
    "#else\n",
    "precision highp float;\n",
    "precision highp int;\n",
    "precision highp sampler2D;\n",
    "#endif\n",
    "#endif\n",
    "\n",
    "#if RBL_GLSL >= 300\n",
    "#define RBL_ATTRIBUTE in\n",
    "#define RBL_FLAT flat\n",
    "#ifdef RBL_VERTEX_STAGE\n",
    "#define RBL_VARYING out\n",
    "#else\n",
    "#define RBL_VARYING in\n",
    "#endif\n",
    "#define rblFetch(map, at, n) texelFetch(map, at, 0)\n",
    "#else\n",
    "#define RBL_ATTRIBUTE attribute\n",
    "#define RBL_VARYING varying\n",
    "#define RBL_FLAT\n",
    "#define texture texture2D\n",
    "#define rblFetch(map, at, n) texture2D(map, (vec2(at) + 0.5)/(n))\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_fullscreen_vs[] = {
    "// Full-screen triangle from gl_VertexID (deferred ambient/unbounded-light pass and resolve); no\n",
    "// vertex buffer.\n",
    "#include \"dialect.glsl\"\n",
    "\n",
    "RBL_VARYING vec2 fragUv;                        // G-buffer coordinate of this pixel (0..1)\n",
    "\n",
    "void main()\n",
    "{\n",
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));     // (0,0) (2,0) (0,2)\n",
    "    fragUv = p;\n",
    "    gl_Position = vec4(p*2.0 - 1.0, 0.0, 1.0);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_gbuffer_fs[] = {
    "// Deferred geometry pass, fragment stage: the forward path's material decoding, packed into the\n",
    "// G-buffer (layout: gbuffer_codec.glsl) instead of being lit. The emission (material data, like the\n",
    "// albedo) and the occlusion go to the accumulation target; the scene's ambient is added once per\n",
    "// pixel by the resolve, not per overdrawn layer here.\n",
    "#include \"material.glsl\"\n",
    "#include \"gbuffer_codec.glsl\"\n",
    "\n",
    "layout(location = 0) out vec4 rblOutAlbedo;\n",
    "layout(location = 1) out vec4 rblOutNormal;\n",
    "layout(location = 2) out vec4 rblOutParams;\n",
    "layout(location = 3) out vec4 rblOutAccum;\n",
    "#ifdef RBL_GB_THIN\n",
    "// RT4 where the context has 5 draw buffers: every geometry variant writes it (zero without the\n",
    "// features), so a G-buffer with the thin target never keeps a hidden layer's values; a G-buffer\n",
    "// without it has no 5th draw buffer and the output goes nowhere\n",
    "layout(location = 4) out vec4 rblOutThin;\n",
    "#endif\n",
    "#ifdef RBL_RELIEF_STEPS\n",
    "// The scene's first RBL_LIGHTS lights (as lights.glsl declares them), each marched through the relief\n",
    "uniform int rblLightCount;\n",
    "uniform vec4 rblLightPosition[RBL_LIGHTS];\n",
    "#endif\n",
    "\n",
    "void main()\n",
    "{\n",
    "    float alpha;\n",
    "    vec3 emission, tangentNormal;\n",
    "    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);\n",
    "#if RBL_BRDF == 1\n",
    "    // Blinn-Phong: the specular colour is folded into one intensity (its luminance; white in the G-buffer)\n",
    "    float specular = sp.specular*dot(sp.specularColor, vec3(0.2126, 0.7152, 0.0722));\n",
    "    uint field1 = rblQuantize(rblEncodeShininess(sp.shininess), RBL_GB_FIELD1_BITS);\n",
    "    uint field2 = rblQuantize(rblEncodeIntensity(specular), RBL_GB_FIELD2_BITS);\n",
    "#elif RBL_BRDF == 2\n",
    "    uint field1 = rblQuantize(rblEncodeRoughness(sp.roughness), RBL_GB_FIELD1_BITS);\n",
    "    uint field2 = rblQuantize(sp.metalness, RBL_GB_FIELD2_BITS);\n",
    "#else\n",
    "    uint field1 = 0u;                      // Lambert reads neither; the debug output shows the map\n",
    "    uint field2 = rblQuantize(sp.specular, RBL_GB_FIELD2_BITS);\n",
    "#endif\n",
    "    vec2 params;\n",
    "    float albedoA;\n",
    "    rblPackWord(sp.normal, field1, field2, rblOutNormal, albedoA, params);\n",
    "    rblOutAlbedo = vec4(rblLinearToSrgb(sp.albedo), albedoA);\n",
    "    // RG8 keeps x, y (raylib samples it r,r,r,g: read back as .ra); RGBA8 (ES, or a G-buffer that\n",
    "    // receives shadows) also the caster identity (gbuffer_read.glsl)\n",
    "    rblOutParams = vec4(params.x, params.y, sp.caster);\n",
    "    rblOutAccum = vec4(emission, sp.occlusion);\n",
    "#ifdef RBL_GB_THIN\n",
    "    // Relief: bit i set where the scene's light i is behind relief (lights.glsl's l, at the unquantised\n",
    "    // position), for the light passes to read; transmission: the share in 16 bits (8 would leave\n",
    "    // 2/255 in dark sRGB output under a bright light behind)\n",
    "    float mask = 0.0;\n",
    "#ifdef RBL_RELIEF_STEPS\n",
    "    for (int i = 0; i < RBL_LIGHTS; i++)\n",
    "    {\n",
    "        if (i >= rblLightCount) break;\n",
    "        vec4 p = rblLightPosition[i];\n",
    "        if (rblReliefShadow(rblSafeNormalize(p.xyz - sp.position*p.w, sp.normal)) == 0.0) mask += exp2(float(i));\n",
    "    }\n",
    "#endif\n",
    "    float t = floor(clamp(sp.transmission, 0.0, 1.0)*65535.0 + 0.5);\n",
    "    rblOutThin = vec4(floor(t/256.0), mod(t, 256.0), mask, 0.0)/255.0;\n",
    "#endif\n",
    "}\n",
    NULL };
static const char *const rbl__shader_gbuffer_codec[] = {
    "// G-buffer codec: how the geometry pass packs a surface into 10 bytes per pixel and the lighting\n",
    "// passes unpack it (RblLoadGBuffer; position is never stored, it comes back from depth):\n",
    "//   RT0 RGBA8    rgb albedo, sRGB-encoded (8-bit steps where the eye needs them), a bits 23..16 of the word\n",
    "//   RT1 RGBA8    bits 55..24 of a 56-bit normal/material word, RT1.r its most significant byte\n",
    "//   RT2 RG8      bits 15..0 of the word\n",
    "//   RT3 RGBA16F  light accumulation: emission from the geometry pass, then the lights; alpha keeps\n",
    "//                the occlusion (light passes add alpha 0), which scales the ambient the resolve adds\n",
    "//   RT4 RGBA8    RblGBufferDesc.transmission or .relief only: rg the transmission share in 16 bits\n",
    "//                (r high), b the relief bits of the scene's first 8 lights (bit i: light i behind relief)\n",
    "//   word         normal x | normal y | field 1 | field 2, from the most significant bit; per BRDF:\n",
    "//     GGX          normal 18 + 18 | roughness 12 | metalness 8\n",
    "//     Blinn-Phong  normal 16 + 16 | shininess 12 | specular intensity 12 (colour folded to its luminance)\n",
    "//     Lambert      normal 18 + 18 | 0 12 | the specular map 8 (the debug view)\n",
    "// The split follows what each BRDF's error is made of. A normal off by d moves a highlight's flank by\n",
    "// about (lobe sharpness) x d: GGX needs 36 bits at its sharpest lobe (alpha = 0.045^2), a Blinn-Phong\n",
    "// lobe (n <= 2048) is at least 25 times wider and keeps the same error with 32. A constant material\n",
    "// value rounded to its nearest code is the same error on every pixel, a bias the image's mean shows:\n",
    "// Blinn-Phong's 4 spare bits go to its two fields (12 + 12 instead of 11 + 9). Every field is stored\n",
    "// in the form whose step is the same relative change of what the BRDF reads (a highlight's error is\n",
    "// relative), except metalness (linear in the output). Not stored: the normal's third coordinate,\n",
    "// roughness below RBL_MIN_ROUGHNESS (the BRDF clamps it), F0, the (n + 8)/8 normalisation.\n",
    "//   normal       octahedral (Cigolle et al. 2014), L = 2^b - 1 levels per coordinate, odd so that 0 and\n",
    "//                +-1 are codes (axis-aligned normals exact); of the 4 neighbouring codes the one\n",
    "//                decoding nearest the normal\n",
    "//   roughness    log over [RBL_MIN_ROUGHNESS, 1], 4095 steps\n",
    "//   metalness    linear, 255 steps (0 and 1 exact)\n",
    "//   shininess    log2(n)/11, 4095 steps (n in 1..2048)\n",
    "//   intensity    log2(1 + 256 s)/9, 4095 steps: relative above 1/256, linear toward 0 (0 exact), s <= 511/256\n",
    "#include \"common.glsl\"\n",
    "\n",
    "#if RBL_BRDF == 1\n",
    "#define RBL_GB_NORMAL_BITS 16u          // per coordinate\n",
    "#define RBL_GB_FIELD1_BITS 12u          // shininess\n",
    "#define RBL_GB_FIELD2_BITS 12u          // specular intensity\n",
    "#else\n",
    "#define RBL_GB_NORMAL_BITS 18u          // per coordinate\n",
    "#define RBL_GB_FIELD1_BITS 12u          // roughness (Lambert: 0)\n",
    "#define RBL_GB_FIELD2_BITS 8u           // metalness (Lambert: specular map)\n",
    "#endif\n",
    "#define RBL_GB_NORMAL_LEVELS ((1u << RBL_GB_NORMAL_BITS) - 1u)\n",
    "#define RBL_GB_FIELDS_BITS (RBL_GB_FIELD1_BITS + RBL_GB_FIELD2_BITS)\n",
    "\n",
    "// Octahedral map of a unit vector onto [-1,1]^2 and back (the lower hemisphere folded over the diagonals)\n",
    "vec2 rblOctahedral(vec3 n)\n",
    "{\n",
    "    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);\n",
    "    vec2 e = n.xy;\n",
    "    if (n.z < 0.0) e = (1.0 - abs(n.yx))*vec2((n.x >= 0.0)? 1.0 : -1.0, (n.y >= 0.0)? 1.0 : -1.0);\n",
    "    return e;\n",
    "}\n",
    "\n",
    "vec3 rblOctahedralDecode(vec2 e)\n",
    "{\n",
    "    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));\n",
    "    float t = max(-n.z, 0.0);\n",
    "    n.xy += vec2((n.x >= 0.0)? -t : t, (n.y >= 0.0)? -t : t);\n",
    "    return normalize(n);        // |n| >= 1/sqrt(3): never zero\n",
    "}\n",
    "\n",
    "// Normal code: the nearest of the 4 codes around the octahedral point (rounding each coordinate\n",
    "// alone can pick a farther one: the map's cells are sheared). Compared as |d - n|^2, which float\n",
    "// resolves at these angles (1 - cos would not).\n",
    "uvec2 rblPackNormal(vec3 n)\n",
    "{\n",
    "    float centre = float(RBL_GB_NORMAL_LEVELS - 1u)*0.5;\n",
    "    vec2 f = clamp(rblOctahedral(n)*centre + centre, 0.0, 2.0*centre);\n",
    "    vec2 base = floor(f), q = base;\n",
    "    float best = 1e30;\n",
    "    for (int k = 0; k < 4; k++)\n",
    "    {\n",
    "        vec2 c = min(base + vec2(float(k & 1), float(k >> 1)), vec2(2.0*centre));\n",
    "        vec3 d = rblOctahedralDecode((c - centre)/centre) - n;\n",
    "        float e = dot(d, d);\n",
    "        if (e < best) { best = e; q = c; }\n",
    "    }\n",
    "    return uvec2(q);\n",
    "}\n",
    "\n",
    "vec3 rblUnpackNormal(uvec2 code)\n",
    "{\n",
    "    float centre = float(RBL_GB_NORMAL_LEVELS - 1u)*0.5;\n",
    "    return rblOctahedralDecode((vec2(code) - centre)/centre);\n",
    "}\n",
    "\n",
    "// Fields in [0,1] <-> codes of b bits\n",
    "uint rblQuantize(float t, uint bits) { return uint(floor(clamp(t, 0.0, 1.0)*float((1u << bits) - 1u) + 0.5)); }\n",
    "float rblDequantize(uint code, uint bits) { return float(code)/float((1u << bits) - 1u); }\n",
    "\n",
    "float rblEncodeRoughness(float r) { return 1.0 - log2(clamp(r, RBL_MIN_ROUGHNESS, 1.0))/log2(RBL_MIN_ROUGHNESS); }\n",
    "float rblDecodeRoughness(float t) { return exp2(log2(RBL_MIN_ROUGHNESS)*(1.0 - t)); }\n",
    "float rblEncodeShininess(float n) { return log2(max(n, 1.0))/11.0; }\n",
    "float rblDecodeShininess(float t) { return exp2(t*11.0); }\n",
    "float rblEncodeIntensity(float s) { return log2(1.0 + 256.0*max(s, 0.0))/9.0; }\n",
    "float rblDecodeIntensity(float t) { return (exp2(t*9.0) - 1.0)/256.0; }\n",
    "\n",
    "// The 56-bit word as RT1 (4 bytes), RT0's alpha and RT2 (2 bytes), each byte /255 as an 8-bit target\n",
    "// stores it: hi = bits 55..24, lo = bits 23..0. The fields (at most 24 bits together) lie in lo; the\n",
    "// normal's y code straddles the two where they are fewer than 24 (shifts by 0 otherwise).\n",
    "#define RBL_GB_HI_SHIFT (RBL_GB_NORMAL_BITS + RBL_GB_FIELDS_BITS - 24u)     // x code's lowest bit in hi\n",
    "#define RBL_GB_Y_SPLIT (24u - RBL_GB_FIELDS_BITS)                           // y code's low bits in lo\n",
    "\n",
    "void rblPackWord(vec3 normal, uint field1, uint field2, out vec4 rt1, out float rt0a, out vec2 rt2)\n",
    "{\n",
    "    uvec2 q = rblPackNormal(normal);\n",
    "    uint hi = (q.x << RBL_GB_HI_SHIFT) | (q.y >> RBL_GB_Y_SPLIT);\n",
    "    uint lo = ((q.y << RBL_GB_FIELDS_BITS) & 16777215u) | (field1 << RBL_GB_FIELD2_BITS) | field2;\n",
    "    rt1 = vec4(float(hi >> 24u), float((hi >> 16u) & 255u), float((hi >> 8u) & 255u), float(hi & 255u))/255.0;\n",
    "    rt0a = float(lo >> 16u)/255.0;\n",
    "    rt2 = vec2(float((lo >> 8u) & 255u), float(lo & 255u))/255.0;\n",
    "}\n",
    "\n",
    "void rblUnpackWord(vec4 rt1, float rt0a, vec2 rt2, out vec3 normal, out uint field1, out uint field2)\n",
    "{\n",
    "    uvec4 a = uvec4(floor(rt1*255.0 + 0.5));\n",
    "    uvec3 b = uvec3(floor(vec3(rt0a, rt2)*255.0 + 0.5));\n",
    "    uint hi = (a.x << 24u) | (a.y << 16u) | (a.z << 8u) | a.w;\n",
    "    uint lo = (b.x << 16u) | (b.y << 8u) | b.z;\n",
    "    uint mask = (1u << RBL_GB_NORMAL_BITS) - 1u;\n",
    "    normal = rblUnpackNormal(uvec2(hi >> RBL_GB_HI_SHIFT, ((hi << RBL_GB_Y_SPLIT) | (lo >> RBL_GB_FIELDS_BITS)) & mask));\n",
    "    field1 = (lo >> RBL_GB_FIELD2_BITS) & ((1u << RBL_GB_FIELD1_BITS) - 1u);\n",
    "    field2 = lo & ((1u << RBL_GB_FIELD2_BITS) - 1u);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_gbuffer_read[] = {
    "// G-buffer read: the targets of the geometry pass as a lighting pass sees them, the world position\n",
    "// rebuilt from depth, and the surface unpacked (gbuffer_codec.glsl).\n",
    "#include \"surface.glsl\"\n",
    "#include \"gbuffer_codec.glsl\"\n",
    "\n",
    "uniform sampler2D rblGAlbedo;           // RGBA8: sRGB albedo, bits 23..16 of the normal/material word\n",
    "uniform sampler2D rblGNormal;           // RGBA8: bits 55..24\n",
    "uniform sampler2D rblGParams;           // RG8: bits 15..0; RBL_GB_PARAMS_RGBA: RGBA8, ba the caster identity\n",
    "uniform sampler2D rblGDepth;            // depth texture of the geometry pass\n",
    "uniform sampler2D rblGAccum;            // RGBA16F light accumulation (resolve only)\n",
    "uniform vec4 rblDepthLinear;            // perspective: n*f, f - n, f, 1; orthographic: n, f - n, 0, 0\n",
    "uniform vec2 rblInvP;                   // 1/P00, 1/P11 of the geometry pass's projection\n",
    "uniform mat4 rblInvView;                // inverse view (camera to world)\n",
    "uniform vec3 rblEye;                    // camera position\n",
    "uniform vec4 rblViewAxis;               // camera back direction, w 1 orthographic (rblViewVector)\n",
    "#ifdef RBL_GB_THIN\n",
    "uniform sampler2D rblGThin;             // RGBA8: transmission share (rg, 16 bits), relief bits of lights 0..7 (b)\n",
    "#endif\n",
    "#ifdef RBL_GB_RELIEF\n",
    "uniform int rblReliefIndex[RBL_LIGHTS]; // full-screen pass: the scene index of light slot i (-1: no bit)\n",
    "uint rblGbReliefMask;                   // this pixel's relief bits (rblGBufferSurface)\n",
    "int rblGbReliefLight = -1;              // scene index of the light being evaluated (-1: none marched)\n",
    "\n",
    "// Light slot i of the full-screen pass is evaluated next\n",
    "void rblGbReliefSelect(int i) { rblGbReliefLight = rblReliefIndex[i]; }\n",
    "\n",
    "// The stored relief verdict for the light being evaluated (lights.glsl): 0 behind relief, else 1\n",
    "float rblReliefShadow(vec3 l)\n",
    "{\n",
    "    if ((rblGbReliefLight < 0) || (rblGbReliefLight > 7)) return 1.0;\n",
    "    return (((rblGbReliefMask >> uint(rblGbReliefLight)) & 1u) != 0u)? 0.0 : 1.0;\n",
    "}\n",
    "#endif\n",
    "\n",
    "// This pixel's G-buffer texel and depth in a light pass (drawn at the G-buffer's size); false where\n",
    "// nothing was drawn (background)\n",
    "bool rblLightPassTexel(out ivec2 texel, out float depth)\n",
    "{\n",
    "    texel = ivec2(gl_FragCoord.xy);\n",
    "    depth = texelFetch(rblGDepth, texel, 0).r;\n",
    "    return depth < 1.0;\n",
    "}\n",
    "\n",
    "// World position from the depth buffer, in closed form (an inverse projection matrix would cancel two\n",
    "// large terms). Perspective: view distance z = n f/(f - d (f - n)) from the window depth d, then x, y\n",
    "// along the pixel's ray. Orthographic: z = n + d (f - n), x, y straight from NDC. Then the inverse view.\n",
    "vec3 rblPositionFromDepth(ivec2 texel, float depth)\n",
    "{\n",
    "    vec2 ndc = (vec2(texel) + 0.5)/vec2(textureSize(rblGDepth, 0))*2.0 - 1.0;\n",
    "    vec3 view;\n",
    "    if (rblDepthLinear.w > 0.0)\n",
    "    {\n",
    "        float z = rblDepthLinear.x/(rblDepthLinear.z - depth*rblDepthLinear.y);\n",
    "        view = vec3(ndc*rblInvP*z, -z);\n",
    "    }\n",
    "    else view = vec3(ndc*rblInvP, -(rblDepthLinear.x + depth*rblDepthLinear.y));\n",
    "    return (rblInvView*vec4(view, 1.0)).xyz;\n",
    "}\n",
    "\n",
    "#if RBL_SHADOWS > 0\n",
    "// The rasterised surface's normal at texel (for shadow biasing, as the forward path's screen\n",
    "// derivatives): from the positions of the neighbours on each axis, the one whose depth differs less\n",
    "// (the same surface, across an edge); the shading normal where neither lies on a surface\n",
    "vec3 rblFaceNormal(ivec2 texel, vec3 position, float depth, vec3 fallback)\n",
    "{\n",
    "    ivec2 top = textureSize(rblGDepth, 0) - 1;\n",
    "    vec3 d[2];\n",
    "    for (int axis = 0; axis < 2; axis++)\n",
    "    {\n",
    "        ivec2 step = (axis == 0)? ivec2(1, 0) : ivec2(0, 1);\n",
    "        ivec2 a = min(texel + step, top), b = max(texel - step, ivec2(0));\n",
    "        float da = texelFetch(rblGDepth, a, 0).r, db = texelFetch(rblGDepth, b, 0).r;\n",
    "        bool useA = (a != texel) && (da < 1.0) && ((b == texel) || (db >= 1.0) || (abs(da - depth) <= abs(db - depth)));\n",
    "        bool useB = !useA && (b != texel) && (db < 1.0);\n",
    "        d[axis] = useA? rblPositionFromDepth(a, da) - position : (useB? position - rblPositionFromDepth(b, db) : vec3(0.0));\n",
    "    }\n",
    "    return rblSafeNormalize(cross(d[0], d[1]), fallback);\n",
    "}\n",
    "#endif\n",
    "\n",
    "RblShadingPoint rblGBufferSurface(ivec2 texel, vec3 position)\n",
    "{\n",
    "    vec4 a = texelFetch(rblGAlbedo, texel, 0);\n",
    "    vec4 n = texelFetch(rblGNormal, texel, 0);\n",
    "    vec4 p = texelFetch(rblGParams, texel, 0);\n",
    "    RblShadingPoint s;\n",
    "    s.position = position;\n",
    "    uint field1, field2;\n",
    "#ifdef RBL_GB_PARAMS_RGBA\n",
    "    rblUnpackWord(n, a.a, p.rg, s.normal, field1, field2);\n",
    "    s.caster = p.ba;\n",
    "#else\n",
    "    rblUnpackWord(n, a.a, p.ra, s.normal, field1, field2);     // raylib samples RG8 (GRAY_ALPHA) as (r, r, r, g)\n",
    "    s.caster = vec2(0.0);                   // no room for it: every caster counts\n",
    "#endif\n",
    "    s.albedo = rblSrgbToLinear(a.rgb);\n",
    "#if RBL_SHADOWS > 0\n",
    "    s.face = rblFaceNormal(texel, position, texelFetch(rblGDepth, texel, 0).r, s.normal);\n",
    "#else\n",
    "    s.face = s.normal;\n",
    "#endif\n",
    "    s.occlusion = 1.0;                  // the accumulation's alpha (the resolve reads it)\n",
    "    s.transmission = 0.0;\n",
    "#ifdef RBL_GB_THIN\n",
    "    vec4 thin = floor(texelFetch(rblGThin, texel, 0)*255.0 + 0.5);\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    s.transmission = (thin.r*256.0 + thin.g)/65535.0;\n",
    "#endif\n",
    "#ifdef RBL_GB_RELIEF\n",
    "    rblGbReliefMask = uint(thin.b);\n",
    "#endif\n",
    "#endif\n",
    "    s.specularColor = vec3(1.0);\n",
    "    s.shininess = 1.0;\n",
    "    s.metalness = 0.0;\n",
    "    s.roughness = 0.5;\n",
    "#if RBL_BRDF == 1\n",
    "    s.shininess = rblDecodeShininess(rblDequantize(field1, RBL_GB_FIELD1_BITS));\n",
    "    s.specular = rblDecodeIntensity(rblDequantize(field2, RBL_GB_FIELD2_BITS));\n",
    "#elif RBL_BRDF == 2\n",
    "    s.roughness = rblDecodeRoughness(rblDequantize(field1, RBL_GB_FIELD1_BITS));\n",
    "    s.metalness = rblDequantize(field2, RBL_GB_FIELD2_BITS);\n",
    "    s.specular = s.roughness;           // the debug view shows the stored channel\n",
    "#else\n",
    "    s.specular = rblDequantize(field2, RBL_GB_FIELD2_BITS);\n",
    "#endif\n",
    "    return s;\n",
    "}\n",
    NULL };
static const char *const rbl__shader_light_grid[] = {
    "// Light grid: every light of the scene for programs compiled with RblLitShaderDesc.clustered (GLSL 3:\n",
    "// GL 3.3, ES 3, WebGL2). RblSetScene packs the lights into one texture and builds one world-space grid\n",
    "// over the spheres of the bounded lights: each cell lists the lights that reach it. Unbounded lights\n",
    "// (directional, range 0, or a range as large as the light set) are listed once and lit everywhere. A\n",
    "// world grid serves every camera, target and pass of the frame, and needs no camera to build.\n",
    "//   RBL_LIGHT_GRID            the grid replaces the light slots (RBL_LIGHTS is 0)\n",
    "// Mirrors of the C side (rbl__LightGrid): RBL_LIGHT_GRID_WIDTH entries per row of rblLightGrid,\n",
    "// RBL_LIGHT_DATA_LIGHTS lights of 4 texels per row of rblLightData.\n",
    "#include \"common.glsl\"\n",
    "\n",
    "#ifdef RBL_LIGHT_GRID\n",
    "#define RBL_LIGHT_GRID_WIDTH 2048           // power of two: row = i >> 11\n",
    "#define RBL_LIGHT_DATA_LIGHTS 256           // power of two: row = light >> 8\n",
    "uniform highp sampler2D rblLightData;       // RGBA32F, unit RBL_LIGHT_GRID_TEXTURE_UNIT; per light: position (w: its RblLightFeature bits), colour (a: 1/range), spot, falloff\n",
    "uniform highp sampler2D rblLightGrid;       // R32F, unit RBL_LIGHT_GRID_TEXTURE_UNIT + 1: the unbounded lights, the cells' starts (cells + 1), then each cell's lights\n",
    "uniform vec4 rblGridOrigin;                 // xyz world corner of cell (0, 0, 0), w 1/cell size\n",
    "uniform ivec4 rblGridDims;                  // cells along x, y, z (0: no bounded light); w the unbounded lights (the first entries)\n",
    "\n",
    "// Light types this program leaves out, as the slots do (point lights are always compiled)\n",
    "#ifdef RBL_LIGHT_DIRECTIONAL\n",
    "#define RBL_GRID_NO_DIRECTIONAL 0\n",
    "#else\n",
    "#define RBL_GRID_NO_DIRECTIONAL 2\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_SPOT\n",
    "#define RBL_GRID_NO_SPOT 0\n",
    "#else\n",
    "#define RBL_GRID_NO_SPOT 4\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_CLASSIC\n",
    "#define RBL_GRID_NO_CLASSIC 0\n",
    "#else\n",
    "#define RBL_GRID_NO_CLASSIC 8\n",
    "#endif\n",
    "#define RBL_GRID_SKIPPED (RBL_GRID_NO_DIRECTIONAL + RBL_GRID_NO_SPOT + RBL_GRID_NO_CLASSIC)\n",
    "\n",
    "// Entry i of the grid list (a light index, or a cell's first entry)\n",
    "int rblGridEntry(int i)\n",
    "{\n",
    "    return int(texelFetch(rblLightGrid, ivec2(i & (RBL_LIGHT_GRID_WIDTH - 1), i >> 11), 0).r);\n",
    "}\n",
    "\n",
    "// Texel t (0 position, 1 colour, 2 spot, 3 falloff) of light i\n",
    "vec4 rblGridLightTexel(int i, int t)\n",
    "{\n",
    "    return texelFetch(rblLightData, ivec2(((i & (RBL_LIGHT_DATA_LIGHTS - 1)) << 2) + t, i >> 8), 0);\n",
    "}\n",
    "\n",
    "// Entries [x, y) listing the bounded lights that may reach world point p (empty outside the grid;\n",
    "// compared as floats first, so a far or NaN position never converts to an out-of-range int)\n",
    "ivec2 rblGridCell(vec3 p)\n",
    "{\n",
    "    vec3 g = floor((p - rblGridOrigin.xyz)*rblGridOrigin.w);\n",
    "    if (!(all(greaterThanEqual(g, vec3(0.0))) && all(lessThan(g, vec3(rblGridDims.xyz))))) return ivec2(0);\n",
    "    ivec3 c = ivec3(g);\n",
    "    int cell = rblGridDims.w + (c.z*rblGridDims.y + c.y)*rblGridDims.x + c.x;\n",
    "    return ivec2(rblGridEntry(cell), rblGridEntry(cell + 1));\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_lights[] = {
    "// Lights: light uniforms, falloff, spot cones, BRDFs (Lambert, normalised Blinn-Phong,\n",
    "// GGX), and the sum over the light slots. Units: a light of linear colour c and intensity I delivers\n",
    "// irradiance E = c*I*attenuation*cone; reflected radiance = pi*BRDF*E*NdotL, pi folded into the\n",
    "// light, so a white Lambert surface lit head-on by E = 1 returns exactly 1.\n",
    "//   RBL_LIGHTS n              light slots\n",
    "//   RBL_LIGHT_GRID            every light of the scene from the light grid instead (light_grid.glsl)\n",
    "//   RBL_LIGHT_DIRECTIONAL     directional lights present (rblLightPosition.w = 0)\n",
    "//   RBL_LIGHT_SPOT            spot cones\n",
    "//   RBL_LIGHT_CLASSIC         constant/linear/quadratic attenuation\n",
    "//   RBL_BRDF b                0 Lambert, 1 normalised Blinn-Phong, 2 GGX (Cook-Torrance)\n",
    "//   RBL_TRANSMISSION          light behind a card shows through it (transmission.glsl)\n",
    "//   RBL_RELIEF_STEPS          each light marched through the relief (rblReliefShadow, material.glsl)\n",
    "//   RBL_GB_RELIEF             deferred: each light's relief bit stored by the geometry pass\n",
    "//                             (rblReliefShadow and rblGbReliefSelect, gbuffer_read.glsl)\n",
    "//   RBL_SHADOW_TINT           blended casters tint the light they let through (shadow_tint.glsl)\n",
    "#include \"surface.glsl\"\n",
    "#include \"ambient.glsl\"\n",
    "#include \"shadows.glsl\"\n",
    "#include \"shadow_tint.glsl\"\n",
    "#include \"transmission.glsl\"\n",
    "#include \"light_grid.glsl\"\n",
    "\n",
    "#define RBL_MIN_NDOTV 1e-4          // grazing views: the visibility term stays finite\n",
    "#define RBL_MIN_DIST2 1e-4          // falloff denominator: a light on the surface stays finite\n",
    "\n",
    "#if (RBL_LIGHTS > 0) && !defined(RBL_LIGHT_GRID)\n",
    "uniform int rblLightCount;\n",
    "uniform vec4 rblLightPosition[RBL_LIGHTS];  // xyz position, w 1; directional: xyz unit vector toward the light, w 0\n",
    "uniform vec4 rblLightColor[RBL_LIGHTS];     // rgb linear colour x intensity, a 1/range (0 = no window)\n",
    "#ifdef RBL_LIGHT_SPOT\n",
    "uniform vec4 rblLightSpot[RBL_LIGHTS];      // xyz cone axis * scale, w offset; (0,0,0,1) = no cone\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_CLASSIC\n",
    "uniform vec3 rblLightAttenuation[RBL_LIGHTS]; // constant, linear, quadratic (windowed lights: 0, 0, 1)\n",
    "#endif\n",
    "#endif\n",
    "#if RBL_SHADOWS > 0\n",
    "uniform ivec4 rblShadowLight;               // light slot (grid: scene light) shadowed by map k (-1 = none)\n",
    "#endif\n",
    "\n",
    "// Radiance reflected toward v per unit irradiance arriving from l (pi folded in), for NdotL > 0\n",
    "vec3 rblBrdf(RblShadingPoint s, vec3 v, vec3 l, float NdotL)\n",
    "{\n",
    "#if RBL_BRDF == 1\n",
    "    // Normalised Blinn-Phong: (n + 8)/(8 pi) NdotH^n, pi folded\n",
    "    vec3 h = rblSafeNormalize(l + v, s.normal);\n",
    "    float NdotH = max(dot(s.normal, h), 0.0);\n",
    "    float n = s.shininess;\n",
    "    return s.albedo + s.specularColor*(s.specular*(n + 8.0)/8.0*pow(NdotH, n));\n",
    "#elif RBL_BRDF == 2\n",
    "    // Cook-Torrance: GGX D, Smith height-correlated V, Schlick F; diffuse Lambert scaled by (1 - metalness)\n",
    "    float perceptual = max(s.roughness, RBL_MIN_ROUGHNESS);\n",
    "    float a = perceptual*perceptual;\n",
    "    float a2 = a*a;\n",
    "    float metal = s.metalness;\n",
    "    vec3 f0 = mix(vec3(0.04), s.albedo, metal);\n",
    "    vec3 h = rblSafeNormalize(l + v, s.normal);\n",
    "    float NdotH = clamp(dot(s.normal, h), 0.0, 1.0);\n",
    "    vec3 nxh = cross(s.normal, h);                              // 1 - NdotH^2 without cancellation\n",
    "    float k = a/(dot(nxh, nxh) + NdotH*NdotH*a2);\n",
    "    float D = k*k*(1.0/RBL_PI);\n",
    "    float NdotV = max(dot(s.normal, v), RBL_MIN_NDOTV);\n",
    "    float V = 0.5/(NdotL*sqrt(NdotV*NdotV*(1.0 - a2) + a2) + NdotV*sqrt(NdotL*NdotL*(1.0 - a2) + a2));\n",
    "    float LdotH = clamp(dot(l, h), 0.0, 1.0);\n",
    "    float fw = pow(1.0 - LdotH, 5.0);\n",
    "    vec3 F = f0 + (1.0 - f0)*fw;\n",
    "    return s.albedo*(1.0 - metal) + (RBL_PI*D*V)*F;\n",
    "#else\n",
    "    return s.albedo;\n",
    "#endif\n",
    "}\n",
    "\n",
    "#if RBL_SHADOWS > 0\n",
    "// Light that map k shadows, at this point: the map's lookup, or 1 (unlit side, or no such light). Done\n",
    "// once per map before the light loop, not per light slot (CPU rasterisers run every branch of a loop)\n",
    "float rblShadowOfMap(int k, RblShadingPoint s, int light)\n",
    "{\n",
    "#ifdef RBL_LIGHT_GRID\n",
    "    if (light < 0) return 1.0;\n",
    "    vec4 p = rblGridLightTexel(light, 0);\n",
    "    p.w = (int(p.w) == 2)? 0.0 : 1.0;               // feature bits 2: directional\n",
    "#elif RBL_GLSL >= 300\n",
    "    if ((light < 0) || (light >= rblLightCount)) return 1.0;\n",
    "    vec4 p = rblLightPosition[light];\n",
    "#else\n",
    "    if ((light < 0) || (light >= rblLightCount)) return 1.0;\n",
    "    vec4 p = vec4(0.0);                             // GLSL ES 1.00: uniform arrays by loop index only\n",
    "    for (int i = 0; i < RBL_LIGHTS; i++) if (i == light) p = rblLightPosition[i];\n",
    "#endif\n",
    "    vec3 l = rblSafeNormalize(p.xyz - s.position*p.w, s.normal);\n",
    "    float NdotL = dot(s.normal, l);\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    if (s.transmission > 0.0) NdotL = 1.0;          // the light behind the card is shadowed on its way too\n",
    "#endif\n",
    "    return (NdotL > 0.0)? rblShadowAt(k, s, l) : 1.0;\n",
    "}\n",
    "#endif\n",
    "\n",
    "// One light at a surface point seen along v: p position (w 0: directional), c colour (a: 1/range),\n",
    "// spot cone (axis*scale, offset; (0,0,0,1) = none), k classic attenuation ((0,0,1) = inverse square),\n",
    "// shadow the fraction its shadow map lets through (1 = unshadowed)\n",
    "vec3 rblEvalLight(RblShadingPoint s, vec3 v, vec4 p, vec4 c, vec4 spot, vec3 k, float shadow)\n",
    "{\n",
    "#ifdef RBL_LIGHT_DIRECTIONAL\n",
    "    vec3 toLight = p.xyz - s.position*p.w;\n",
    "#else\n",
    "    vec3 toLight = p.xyz - s.position;\n",
    "#endif\n",
    "    float d2 = dot(toLight, toLight);\n",
    "    vec3 l = rblSafeNormalize(toLight, s.normal);      // a light on the surface lights it head-on\n",
    "    float NdotL = dot(s.normal, l);\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    if ((NdotL <= 0.0) && !(s.transmission > 0.0)) return vec3(0.0);\n",
    "#else\n",
    "    if (NdotL <= 0.0) return vec3(0.0);\n",
    "#endif\n",
    "    // Windowed inverse square (UE4/Filament): saturate(1 - (d/r)^4)^2/max(d^2, eps)\n",
    "    float x2 = d2*c.a*c.a;\n",
    "    float window = clamp(1.0 - x2*x2, 0.0, 1.0);\n",
    "#ifdef RBL_LIGHT_CLASSIC\n",
    "    float attenuation = window*window/max(k.x + k.y*sqrt(d2) + k.z*d2, RBL_MIN_DIST2);\n",
    "#else\n",
    "    float attenuation = window*window/max(d2, RBL_MIN_DIST2);\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_SPOT\n",
    "    float t = clamp(dot(-l, spot.xyz) + spot.w, 0.0, 1.0);\n",
    "    attenuation *= t*t*(3.0 - 2.0*t);               // smoothstep from the outer to the inner cone\n",
    "#endif\n",
    "    attenuation *= shadow;\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    vec3 through = rblTransmitted(s, NdotL);\n",
    "    if (NdotL <= 0.0) return c.rgb*attenuation*through;\n",
    "#endif\n",
    "#if defined(RBL_RELIEF_STEPS) || defined(RBL_GB_RELIEF)\n",
    "    attenuation *= rblReliefShadow(l);              // transmitted light is not: it comes through the card\n",
    "#endif\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    return c.rgb*attenuation*(NdotL*rblBrdf(s, v, l, NdotL) + through);\n",
    "#else\n",
    "    return c.rgb*(attenuation*NdotL)*rblBrdf(s, v, l, NdotL);\n",
    "#endif\n",
    "}\n",
    "\n",
    "// Sum of the light slots (or of the grid's lights reaching it) at a surface point seen along the unit\n",
    "// view vector v (rblViewVector)\n",
    "vec3 rblDirectLight(RblShadingPoint s, vec3 v)\n",
    "{\n",
    "    vec3 sum = vec3(0.0);\n",
    "#if (RBL_LIGHTS > 0) || defined(RBL_LIGHT_GRID)\n",
    "#if RBL_SHADOWS > 0\n",
    "    vec4 shadowed = vec4(1.0);                      // each map's factor, for the light it shadows\n",
    "    shadowed.x = rblShadowOfMap(0, s, rblShadowLight.x);\n",
    "#if RBL_SHADOWS > 1\n",
    "    shadowed.y = rblShadowOfMap(1, s, rblShadowLight.y);\n",
    "#endif\n",
    "#if RBL_SHADOWS > 2\n",
    "    shadowed.z = rblShadowOfMap(2, s, rblShadowLight.z);\n",
    "#endif\n",
    "#if RBL_SHADOWS > 3\n",
    "    shadowed.w = rblShadowOfMap(3, s, rblShadowLight.w);\n",
    "#endif\n",
    "#ifdef RBL_SHADOW_TINT\n",
    "    vec3 tint0 = rblShadowTint(0, s.position), tint1 = vec3(1.0), tint2 = vec3(1.0), tint3 = vec3(1.0);\n",
    "#if RBL_SHADOWS > 1\n",
    "    tint1 = rblShadowTint(1, s.position);\n",
    "#endif\n",
    "#if RBL_SHADOWS > 2\n",
    "    tint2 = rblShadowTint(2, s.position);\n",
    "#endif\n",
    "#if RBL_SHADOWS > 3\n",
    "    tint3 = rblShadowTint(3, s.position);\n",
    "#endif\n",
    "#endif\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_GRID\n",
    "    // The unbounded lights, then the cell's: one loop, so the body is compiled once\n",
    "    ivec2 cell = rblGridCell(s.position);\n",
    "    int unbounded = rblGridDims.w;\n",
    "    int entries = unbounded + cell.y - cell.x;\n",
    "    for (int e = 0; e < entries; e++)\n",
    "    {\n",
    "        int i = rblGridEntry((e < unbounded)? e : (cell.x + e - unbounded));\n",
    "        vec4 p = rblGridLightTexel(i, 0);\n",
    "        int features = int(p.w);\n",
    "        if ((features & RBL_GRID_SKIPPED) != 0) continue;\n",
    "        p.w = (features == 2)? 0.0 : 1.0;\n",
    "        vec4 c = rblGridLightTexel(i, 1);\n",
    "#ifdef RBL_LIGHT_SPOT\n",
    "        vec4 spot = rblGridLightTexel(i, 2);\n",
    "#else\n",
    "        vec4 spot = vec4(0.0, 0.0, 0.0, 1.0);\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_CLASSIC\n",
    "        vec3 k = rblGridLightTexel(i, 3).xyz;\n",
    "#else\n",
    "        vec3 k = vec3(0.0, 0.0, 1.0);\n",
    "#endif\n",
    "#else\n",
    "    for (int i = 0; i < RBL_LIGHTS; i++)\n",
    "    {\n",
    "        if (i >= rblLightCount) break;\n",
    "        vec4 p = rblLightPosition[i], c = rblLightColor[i];\n",
    "#ifdef RBL_LIGHT_SPOT\n",
    "        vec4 spot = rblLightSpot[i];\n",
    "#else\n",
    "        vec4 spot = vec4(0.0, 0.0, 0.0, 1.0);\n",
    "#endif\n",
    "#ifdef RBL_LIGHT_CLASSIC\n",
    "        vec3 k = rblLightAttenuation[i];\n",
    "#else\n",
    "        vec3 k = vec3(0.0, 0.0, 1.0);\n",
    "#endif\n",
    "#endif\n",
    "#if RBL_SHADOWS > 0\n",
    "        float shadow = (i == rblShadowLight.x)? shadowed.x : ((i == rblShadowLight.y)? shadowed.y :\n",
    "                       ((i == rblShadowLight.z)? shadowed.z : ((i == rblShadowLight.w)? shadowed.w : 1.0)));\n",
    "#else\n",
    "        float shadow = 1.0;\n",
    "#endif\n",
    "#ifdef RBL_GB_RELIEF\n",
    "        rblGbReliefSelect(i);\n",
    "#endif\n",
    "#if (RBL_SHADOWS > 0) && defined(RBL_SHADOW_TINT)\n",
    "        vec3 tint = (i == rblShadowLight.x)? tint0 : ((i == rblShadowLight.y)? tint1 : ((i == rblShadowLight.z)? tint2 : ((i == rblShadowLight.w)? tint3 : vec3(1.0))));\n",
    "        sum += rblEvalLight(s, v, p, c, spot, k, shadow)*tint;\n",
    "#else\n",
    "        sum += rblEvalLight(s, v, p, c, spot, k, shadow);\n",
    "#endif\n",
    "    }\n",
    "#endif\n",
    "    return sum;\n",
    "}\n",
    NULL };
static const char *const rbl__shader_lit_fs[] = {
    "// Forward pass, fragment stage, for billboards and raylib Models: material -> lights -> output, the\n",
    "// same code the deferred passes evaluate.\n",
    "#include \"material.glsl\"\n",
    "#include \"lights.glsl\"\n",
    "#include \"output.glsl\"\n",
    "#include \"soft.glsl\"\n",
    "//   RBL_LINEAR_OUTPUT        write linear light (float targets); default: encode for display\n",
    "//   RBL_DEBUG_OUTPUT v         RblDebugOutput: 1 tangent-space normal, 2 world normal, 3 specular, 4 occlusion (raw)\n",
    "\n",
    "#if RBL_GLSL >= 300\n",
    "out vec4 finalColor;\n",
    "#else\n",
    "#define finalColor gl_FragColor   // GLSL 1.x: the one built-in output\n",
    "#endif\n",
    "\n",
    "void main()\n",
    "{\n",
    "    float alpha;\n",
    "    vec3 emission, tangentNormal;\n",
    "    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);\n",
    "#ifdef RBL_SOFT_PARTICLES\n",
    "    alpha *= rblSoftFade();\n",
    "#endif\n",
    "#ifdef RBL_VIEW_VECTOR\n",
    "    vec3 v = rblViewVector(fragEye, fragViewAxis, fragPosition, sp.normal);\n",
    "    float viewDistance = rblViewDistance(fragEye, fragViewAxis, fragPosition);\n",
    "#else\n",
    "    vec3 v = sp.normal;                      // unused: no view-dependent term compiled\n",
    "    float viewDistance = 0.0;\n",
    "#endif\n",
    "    vec3 color = rblAmbientLight(sp) + rblDirectLight(sp, v) + emission;\n",
    "\n",
    "#if defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 1)\n",
    "    finalColor = vec4(tangentNormal*0.5 + 0.5, 1.0);\n",
    "#elif defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 2)\n",
    "    finalColor = vec4(sp.normal*0.5 + 0.5, 1.0);\n",
    "#elif defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 3)\n",
    "#if RBL_BRDF == 2\n",
    "    finalColor = vec4(vec3(sp.roughness), 1.0);\n",
    "#else\n",
    "    finalColor = vec4(vec3(sp.specular), 1.0);\n",
    "#endif\n",
    "#elif defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 4)\n",
    "    finalColor = vec4(vec3(sp.occlusion), 1.0);\n",
    "#else\n",
    "    finalColor = vec4(rblFinish(color, viewDistance), alpha);\n",
    "#endif\n",
    "}\n",
    NULL };
static const char *const rbl__shader_lit_vs[] = {
    "// Lit vertex stage of vertex-buffer geometry: billboards (world-space vertices, matModel = identity)\n",
    "// and raylib Models (matModel = the model transform) go through the same code. Pairs with lit.fs.glsl,\n",
    "// gbuffer.fs.glsl and shadow_caster.fs.glsl.\n",
    "#include \"common.glsl\"\n",
    "#include \"skinning.glsl\"\n",
    "\n",
    "RBL_ATTRIBUTE vec3 vertexPosition;\n",
    "RBL_ATTRIBUTE vec2 vertexTexCoord;\n",
    "RBL_ATTRIBUTE vec3 vertexNormal;\n",
    "RBL_ATTRIBUTE vec4 vertexColor;\n",
    "RBL_ATTRIBUTE vec4 vertexTangent;      // xyz: world +U direction, w: handedness (cross(N,T)*w = +V)\n",
    "#ifdef RBL_CROSS_FADE\n",
    "// The fade stream (raylib's texcoord2 location 5): xy the second frame's texture coordinate, z the\n",
    "// weight, w its tangent axes against the first's (material.glsl). Without the stream the attribute\n",
    "// is constant (weight 0): the first frame alone\n",
    "RBL_ATTRIBUTE vec4 vertexTexCoord2;\n",
    "RBL_VARYING vec2 fragTexCoord2;\n",
    "RBL_FLAT RBL_VARYING vec2 fragFade;\n",
    "// The stream's second half: each frame's position in its trimmed rectangle (material.glsl\n",
    "// fragFadeClip); its location is the linker's (queried: the 1.x dialects have no layout). Without\n",
    "// the stream it is constant (0 or 1 components: inside)\n",
    "RBL_ATTRIBUTE vec4 rblFadeClip;\n",
    "RBL_VARYING vec4 fragFadeClip;\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_CASTER_ID\n",
    "// The billboard's caster identity (shadow_caster.fs.glsl, shadows.glsl): 16 bits as two normalised\n",
    "// bytes, from the batch's identity stream. rblCasterIdOn is 1 for the header's billboard draws and 0\n",
    "// otherwise: a Model's identity is 0 whatever its buffers hold at this attribute's location\n",
    "RBL_ATTRIBUTE vec4 rblCasterId;\n",
    "uniform float rblCasterIdOn;\n",
    "RBL_FLAT RBL_VARYING vec2 fragCasterId;\n",
    "#endif\n",
    "\n",
    "uniform mat4 mvp;\n",
    "uniform mat4 matModel;\n",
    "uniform mat4 matNormal;\n",
    "#ifdef RBL_VIEW_VECTOR\n",
    "uniform mat4 matView;       // raylib's DrawMesh and the billboard paths set both: no viewPos glue needed\n",
    "uniform mat4 matProjection;\n",
    "RBL_FLAT RBL_VARYING vec3 fragEye;\n",
    "RBL_FLAT RBL_VARYING vec4 fragViewAxis; // back direction, w 1 orthographic (common.glsl rblViewVector)\n",
    "#endif\n",
    "\n",
    "RBL_VARYING vec3 fragPosition;\n",
    "RBL_VARYING vec2 fragTexCoord;\n",
    "RBL_VARYING vec4 fragColor;\n",
    "RBL_VARYING vec3 fragNormal;\n",
    "RBL_VARYING vec4 fragTangent;\n",
    "\n",
    "void main()\n",
    "{\n",
    "    vec3 position = vertexPosition, normal = vertexNormal, tangent = vertexTangent.xyz;\n",
    "#ifdef RBL_SKINNING\n",
    "    rblSkin(position, normal, tangent);     // bind pose -> animated pose, in the model's space\n",
    "#endif\n",
    "    fragPosition = vec3(matModel*vec4(position, 1.0));\n",
    "    fragTexCoord = vertexTexCoord;\n",
    "#ifdef RBL_CASTER_ID\n",
    "    fragCasterId = rblCasterId.xy*rblCasterIdOn;\n",
    "#endif\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    fragTexCoord2 = vertexTexCoord2.xy;\n",
    "    fragFade = vertexTexCoord2.zw;\n",
    "    fragFadeClip = rblFadeClip;\n",
    "#endif\n",
    "    fragColor = vec4(rblSrgbToLinear(vertexColor.rgb), vertexColor.a);     // sRGB like every raylib Color: decoded once per vertex\n",
    "    fragNormal = rblMat3(matNormal)*normal;\n",
    "    // Tangents transform with the model matrix (they lie in the surface), normals with its inverse transpose.\n",
    "    fragTangent = vec4(rblMat3(matModel)*tangent, vertexTangent.w);\n",
    "#ifdef RBL_VIEW_VECTOR\n",
    "    vec3 t = matView[3].xyz;                                // view = [R|t]: eye = -R^T t\n",
    "    fragEye = -vec3(dot(matView[0].xyz, t), dot(matView[1].xyz, t), dot(matView[2].xyz, t));\n",
    "    // Orthographic: clip w does not depend on the position (the projection's last row is 0 0 0 w);\n",
    "    // an unset matProjection (all zero) counts as perspective, the pre-ortho behaviour\n",
    "    bool parallel = (matProjection[0][3] == 0.0) && (matProjection[1][3] == 0.0) && (matProjection[2][3] == 0.0) && (matProjection[3][3] != 0.0);\n",
    "    fragViewAxis = vec4(rblSafeNormalize(vec3(matView[0][2], matView[1][2], matView[2][2]), vec3(0.0, 0.0, 1.0)), parallel? 1.0 : 0.0);\n",
    "#endif\n",
    "    gl_Position = mvp*vec4(position, 1.0);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_lit_instanced_vs[] = {
    "// Instanced billboard vertex stage: expands one quad per instance (6 vertices, gl_VertexID 0..5)\n",
    "// from per-instance data. Each function mirrors the CPU function of the same name in the header's\n",
    "// geometry section (rblSinCosDeg = rbl__sinCosDeg, rblFacingBasis = rbl__facingBasis,\n",
    "// rblBillboardVertex = one corner of rbl__billboardVertices), with the same degenerate-frame\n",
    "// fallbacks, so all three paths emit the same vertices. Pairs with lit.fs.glsl, gbuffer.fs.glsl and\n",
    "// shadow_caster.fs.glsl.\n",
    "#include \"common.glsl\"\n",
    "\n",
    "// An RblInstance, or in the resident-sprite variant (RBL_SPRITE_BUFFER, compiled by the header for\n",
    "// RblDrawSpriteBuffer) an RblSpriteInstance whose 32 bytes the same locations read as: 10 pivot,\n",
    "// scale; 11 start (x); 12 rotation, frame, speed (half-float bits), mode, as unsigned shorts; 13 tint\n",
    "#ifdef RBL_BATCH_RECORD\n",
    "// The batch-record variant (RblBatch on GLSL 3 with the header's programs): one record per\n",
    "// billboard, the RblBillboard as added (flags: its rotated-frame and cylinder bits; a FIXED or AXIS\n",
    "// up and axis tamed as the CPU tames them). Its facing, up, axis and roundness are its own, not the\n",
    "// draw's. Locations 6..9 are the cross-fade's elsewhere: record programs have no cross-fade\n",
    "layout(location = 10) in vec3 rblRecordPosition;    // pivot\n",
    "layout(location = 11) in vec4 rblRecordSizeOrigin;  // xy: size (negative mirrors), zw: origin\n",
    "layout(location = 12) in float rblRecordRotation;   // degrees\n",
    "layout(location = 13) in vec4 rblRecordSource;      // x, y, width, height in texels (all zero = whole texture)\n",
    "layout(location = 14) in vec4 rblRecordTint;        // normalised bytes (all zero = white)\n",
    "layout(location = 15) in float rblRecordFacing;     // RblFacing\n",
    "layout(location = 6) in vec3 rblRecordUp;           // as RblInstancedDesc.up\n",
    "layout(location = 7) in vec3 rblRecordAxis;         // as RblInstancedDesc.axis\n",
    "layout(location = 8) in float rblRecordRoundness;   // as RblInstancedDesc.roundness\n",
    "layout(location = 9) in float rblRecordFlags;       // RBL_FRAME_ROTATED, RBL_ROUND_CYLINDER\n",
    "#else\n",
    "layout(location = 10) in vec4 rblInstancePosition;  // xyz: pivot, w: rotation in degrees\n",
    "layout(location = 11) in vec4 rblInstanceSize;      // xy: size (negative mirrors), zw: origin\n",
    "layout(location = 12) in vec4 rblInstanceSource;    // x, y, width, height in texels (all zero = whole texture)\n",
    "layout(location = 13) in vec4 rblInstanceTint;      // normalised bytes (all zero = white)\n",
    "layout(location = 14) in float rblInstanceFlags;    // RblBillboardFlags\n",
    "#endif\n",
    "#ifdef RBL_CROSS_FADE\n",
    "// RblInstancedDesc.fades, a second per-instance buffer (without it: constant, weight 0)\n",
    "layout(location = 15) in vec4 rblInstanceFadeSource; // the second frame, as rblInstanceSource\n",
    "layout(location = 6) in float rblInstanceFadeWeight; // 0..1\n",
    "layout(location = 7) in float rblInstanceFadeFlags;  // its RBL_FRAME_ROTATED bit\n",
    "layout(location = 8) in vec4 rblInstanceFadeClip;   // RblFade.clip[0]: the first frame's trimmed part of the quad (zero = all)\n",
    "layout(location = 9) in vec4 rblInstanceFadeClip2;  // RblFade.clip[1]: the second frame's\n",
    "RBL_VARYING vec2 fragTexCoord2;\n",
    "RBL_FLAT RBL_VARYING vec2 fragFade;                  // weight, tangent axes code (material.glsl rblFadeAxes)\n",
    "RBL_VARYING vec4 fragFadeClip;                       // both frames' positions in their rectangles\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_CASTER_ID\n",
    "RBL_FLAT RBL_VARYING vec2 fragCasterId;              // the instance's caster identity (rblCasterIdOf)\n",
    "#endif\n",
    "\n",
    "uniform mat4 mvp;\n",
    "// Per-draw frame, one upload (uniform calls cost more than the data in most drivers):\n",
    "//   [0] eye, facing code: RblFacing + 8 in a shadow pass with light-facing casters (AXIS tilts turn\n",
    "//       the front face to the light); the batch-record variant's facing is each record's, the code\n",
    "//       adds 8 as above and 16 in an omni pass with light-facing casters (its CAMERA_PLANE cards\n",
    "//       face the light's position, rbl__castFacing)\n",
    "//   [1] right, roundness   [2] up, texture width   [3] back, texture height\n",
    "//   [4] facing up (CAMERA_PLANE: caller up, zero = camera up; FIXED: up, zero = +Y), w: shadow pass\n",
    "//       minimum sine at which the light sees an AXIS billboard (0 = no tilt)\n",
    "//   [5] facing axis (AXIS: locked axis, zero = +Y; FIXED: normal, zero = +Z), w: 1 orthographic camera\n",
    "//   [6] shadow pass light: xyz toward the light (w 0) or its position (w 1); zero outside shadow passes\n",
    "#ifdef RBL_SPRITE_BUFFER\n",
    "//   [7] (the resident-sprite variant only) x: 1, y: the sprites' clock (seconds), z: frame table\n",
    "//       width, w: the atlas's frame count\n",
    "uniform vec4 rblInstancing[8];\n",
    "\n",
    "// A sprite buffer's frame table (RGBA32F, read with texelFetch; rbl__buildFrameTable writes it):\n",
    "//   frame k at texels 3k (source), 3k + 1 (size, origin per unit of scale), 3k + 2 (duration, rotated)\n",
    "//   tag t (-1: every frame, forward) at texels 3 frameCount + 2(t + 1): (first timeline entry,\n",
    "//   entries, period, first pass) and (last frame after an odd / an even count of passes, the tag's\n",
    "//   repeat, a pingpong's first frame duration or 0); then the timeline entries\n",
    "//   (frame, start within the period)\n",
    "uniform highp sampler2D rblFrameTable;\n",
    "#else\n",
    "uniform vec4 rblInstancing[7];\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_POLYGONS\n",
    "// Polygon frames (the variant the header compiles for draws with RBL_FRAME_POLYGON instances or a\n",
    "// sprite buffer of a polygon sheet): rblPolygon x: vertices drawn per instance (the draw's largest\n",
    "// polygon's corners, 6 at least; a quad uses 6, the rest collapse), y: table width in texels, z: lowest\n",
    "// handle in the polygon table. A polygon is kept cut along each frame diagonal (a = b, a + b = 1: the\n",
    "// quad's two triangles meet on one of them; rounded draws) and uncut (flat draws), each cut as\n",
    "// corners: pairs (a, b) of fractions of its frame's source, two a texel, 3 per triangle (each turning\n",
    "// as the quad's (0, 1, 2) seen from the front). Its two header texels hold each cut's first corner\n",
    "// texel and corner count; the plain variant finds them at texel 2 (handle - z) of rblPolygonTable, the\n",
    "// resident-sprite variant at the frame table texel that frame k's texel 3k + 2 names in z (w: 1 + its\n",
    "// most corners, 0 for a quad frame)\n",
    "uniform vec4 rblPolygon;\n",
    "#ifndef RBL_SPRITE_BUFFER\n",
    "uniform highp sampler2D rblPolygonTable;\n",
    "#endif\n",
    "#endif\n",
    "\n",
    "// The instance being expanded, from either layout (main reads it once)\n",
    "vec4 rblPivot;          // xyz pivot, w rotation in degrees\n",
    "vec4 rblSizeOrigin;     // size (negative mirrors), origin\n",
    "vec4 rblSource;         // texels (all zero = whole texture)\n",
    "float rblFlagBits;      // RblBillboardFlags\n",
    "#ifdef RBL_POLYGONS\n",
    "vec4 rblPolygonSpan;    // The instance's polygon header: both diagonal cuts' first corner texel and count\n",
    "vec2 rblPolygonFlat;    // ... and the uncut triangles'\n",
    "bool rblPolygonal;      // ... when it has one (else the quad)\n",
    "#endif\n",
    "#ifdef RBL_CROSS_FADE\n",
    "vec4 rblFadeSource, rblFadeClip0, rblFadeClip1;\n",
    "float rblFadeWeight, rblFadeFlagBits;\n",
    "#endif\n",
    "\n",
    "RBL_VARYING vec3 fragPosition;\n",
    "RBL_VARYING vec2 fragTexCoord;\n",
    "RBL_VARYING vec4 fragColor;\n",
    "RBL_VARYING vec3 fragNormal;\n",
    "RBL_VARYING vec4 fragTangent;\n",
    "#ifdef RBL_VIEW_VECTOR\n",
    "RBL_FLAT RBL_VARYING vec3 fragEye;\n",
    "RBL_FLAT RBL_VARYING vec4 fragViewAxis; // back direction, w 1 orthographic (common.glsl rblViewVector)\n",
    "#endif\n",
    "\n",
    "// Unit v into o, or false with o untouched when v is too short to give a direction (as the CPU's)\n",
    "bool rblNormalizeTo(vec3 v, inout vec3 o)\n",
    "{\n",
    "    float l2 = dot(v, v);\n",
    "    if (!(l2 > 1e-24)) return false;\n",
    "    o = v*inversesqrt(l2);\n",
    "    return true;\n",
    "}\n",
    "\n",
    "// Unit component of v perpendicular to unit n (relative threshold, as on the CPU)\n",
    "bool rblPerpendicular(vec3 v, vec3 n, out vec3 o)\n",
    "{\n",
    "    vec3 p = v - n*dot(v, n);\n",
    "    o = p;\n",
    "    if (!(dot(p, p) > 1e-10*dot(v, v))) return false;\n",
    "    return rblNormalizeTo(p, o);\n",
    "}\n",
    "\n",
    "vec3 rblFallbackUp(vec3 d)\n",
    "{\n",
    "    vec3 a = abs(d);\n",
    "    if ((a.y >= a.x) && (a.y >= a.z)) return vec3(0.0, 0.0, (d.y > 0.0)? -1.0 : 1.0);\n",
    "    return vec3(0.0, 1.0, 0.0);\n",
    "}\n",
    "\n",
    "// Near-degenerate blend (the CPU's rbl__blendWeight, rbl__offAxis, rbl__blendOffAxis): a direction\n",
    "// off the axis n from v, blended with the fallback f's as the sine s between v and n drops from 1/8\n",
    "// to 1/64, where float gives v's direction off n only to about 6e-8/s\n",
    "#define RBL_BLEND_LO 0.015625\n",
    "#define RBL_BLEND_HI 0.125\n",
    "\n",
    "float rblBlendWeight(float s)\n",
    "{\n",
    "    float t = clamp((s - RBL_BLEND_LO)*(1.0/(RBL_BLEND_HI - RBL_BLEND_LO)), 0.0, 1.0);\n",
    "    return t*t*(3.0 - 2.0*t);\n",
    "}\n",
    "\n",
    "float rblOffAxis(vec3 v, vec3 n, out vec3 vp)\n",
    "{\n",
    "    vp = v - n*dot(v, n);\n",
    "    float vv = dot(v, v), pp = dot(vp, vp);\n",
    "    if (!(vv > 1e-24)) return 0.0;\n",
    "    if (pp >= (RBL_BLEND_HI*RBL_BLEND_HI)*vv) return 1.0;\n",
    "    return rblBlendWeight(sqrt(pp/vv));\n",
    "}\n",
    "\n",
    "vec3 rblBlendOffAxis(vec3 vp, float w, vec3 f, vec3 n)\n",
    "{\n",
    "    vec3 c = vec3(0.0);\n",
    "    if (w > 0.0)\n",
    "    {\n",
    "        c = vp*(w*inversesqrt(dot(vp, vp)));\n",
    "        if (w >= 1.0) return c;\n",
    "    }\n",
    "    vec3 fp = f - n*dot(f, n);\n",
    "    c = c + fp*((1.0 - w)*inversesqrt(dot(fp, fp)));\n",
    "    for (int i = 0; i < 2; i++) c = c - n*dot(c, n);\n",
    "    if (!(dot(c, c) > 1e-24)) c = fp;\n",
    "    return c*inversesqrt(dot(c, c));\n",
    "}\n",
    "\n",
    "// fmod(degrees, 360) exactly (as the CPU's fmodf), for |degrees| > 368640: there degrees = m 2^e\n",
    "// with e >= -5, so 32 degrees is the integer m 2^(e + 5), reduced mod 32*360 by doubling\n",
    "float rblReduceDegrees(float degrees)\n",
    "{\n",
    "    uint bits = floatBitsToUint(degrees);\n",
    "    int e = int((bits >> 23) & 255u) - 150;\n",
    "    uint r = ((bits & 0x7fffffu) | 0x800000u) % 11520u;\n",
    "    for (int i = 0; i < e + 5; i++) r = (r*2u) % 11520u;\n",
    "    float f = float(r)/32.0;\n",
    "    return (degrees < 0.0)? -f : f;\n",
    "}\n",
    "\n",
    "// sin and cos of an angle in degrees: reduction to [-45, 45] exact in degrees (multiples of 90 come\n",
    "// out exact), then the same minimax polynomials as the CPU\n",
    "vec2 rblSinCosDeg(float degrees)\n",
    "{\n",
    "    if (abs(degrees) > 368640.0) degrees = rblReduceDegrees(degrees);\n",
    "    int q = int(degrees*(1.0/90.0) + ((degrees < 0.0)? -0.5 : 0.5));      // nearest quadrant (truncation, as C)\n",
    "    float x = (degrees - float(q)*90.0)*(3.14159265358979323846/180.0);\n",
    "    float x2 = x*x;\n",
    "    float sn = x + x*x2*(-1.6666654611e-1 + x2*(8.3321608736e-3 + x2*(-1.9515295891e-4)));\n",
    "    float cs = 1.0 - 0.5*x2 + x2*x2*(4.166664568298827e-2 + x2*(-1.388731625493765e-3 + x2*2.443315711809948e-5));\n",
    "    // Quadrant q: (sin, cos) = (sn, cs), (cs, -sn), (-sn, -cs), (-cs, sn)\n",
    "    bool swap = (q & 1) != 0;\n",
    "    vec2 r = swap? vec2(cs, sn) : vec2(sn, cs);\n",
    "    if ((q & 2) != 0) r.x = -r.x;\n",
    "    if (((q + 1) & 2) != 0) r.y = -r.y;\n",
    "    return r;\n",
    "}\n",
    "\n",
    "// Right r, up u (unit, except CAMERA_PLANE's caller up) and unit normal n of a billboard at position\n",
    "// for facing code (rblInstancing[0].w), from the view frame and the draw's up and axis; a shadow pass\n",
    "// tilts AXIS billboards until the light sees them at the minimum angle. As on the CPU: each mode picks\n",
    "// an axis, a vector v and a fallback f, one blend follows, then the frame is built.\n",
    "void rblFacingBasis(int code, vec3 position, vec3 eye, float orthographic, vec3 viewRight, vec3 viewUp, vec3 viewBack,\n",
    "                    vec3 facingUp, vec3 facingAxis, float minCastSin, vec4 light, out vec3 r, out vec3 u, out vec3 n)\n",
    "{\n",
    "    int facing = code & 3;\n",
    "    bool faceLight = (code & 8) != 0;\n",
    "    r = viewRight; u = viewUp; n = viewBack;\n",
    "    vec3 toEye = (orthographic > 0.5)? viewBack : eye - position;     // a parallel view's eye is at infinity (a directional light's too)\n",
    "    vec3 axis = r, v = u, f = u, a = vec3(0.0, 1.0, 0.0);\n",
    "    bool own = true;\n",
    "    if (facing == 0) { own = dot(facingUp, facingUp) > 1e-24; v = facingUp; }\n",
    "    else if (facing == 1) { own = rblNormalizeTo(toEye, axis); f = cross(axis, r); }\n",
    "    else if (facing == 2)\n",
    "    {\n",
    "        if (dot(facingAxis, facingAxis) > 1e-24) rblNormalizeTo(facingAxis, a);\n",
    "        vec3 q;\n",
    "        float wb = rblOffAxis(viewBack, a, q);\n",
    "        axis = a; v = toEye; f = rblBlendOffAxis(q, wb, viewUp, a);\n",
    "    }\n",
    "    else\n",
    "    {\n",
    "        axis = vec3(0.0, 0.0, 1.0);\n",
    "        if (dot(facingAxis, facingAxis) > 1e-24) rblNormalizeTo(facingAxis, axis);\n",
    "        v = (dot(facingUp, facingUp) > 1e-24)? facingUp : vec3(0.0, 1.0, 0.0); f = rblFallbackUp(axis);\n",
    "    }\n",
    "    if (!own) return;\n",
    "    vec3 p;\n",
    "    float w = rblOffAxis(v, axis, p);\n",
    "    vec3 d = rblBlendOffAxis(p, w, f, axis);\n",
    "    if (facing == 0)\n",
    "    {\n",
    "        n = cross(r, d);\n",
    "        u = facingUp;\n",
    "        if (w < 1.0) u = r*dot(facingUp, r) + d*sqrt(dot(p, p));\n",
    "    }\n",
    "    else if (facing == 1) { n = axis; u = d; r = cross(u, n); }\n",
    "    else if (facing == 2)\n",
    "    {\n",
    "        vec3 nn = d;\n",
    "        u = a; n = nn; r = cross(u, n);\n",
    "        vec3 l = a;\n",
    "        if ((minCastSin > 0.0) && rblNormalizeTo(light.xyz - position*light.w, l))\n",
    "        {\n",
    "            float ln = dot(l, n), la = dot(l, a);\n",
    "            float x = faceLight? ln : abs(ln), y = abs(la), rho = sqrt(x*x + y*y);\n",
    "            if ((x < minCastSin) && (rho > 0.0))\n",
    "            {\n",
    "                float k = min(minCastSin/rho, 1.0), m = sqrt(1.0 - k*k);\n",
    "                float sg = faceLight? ((la >= 0.0)? 1.0 : -1.0) : (((ln >= 0.0) == (la >= 0.0))? 1.0 : -1.0);\n",
    "                float c = (k*x + m*y)/rho, sn = (k*y - m*x)/rho*sg;\n",
    "                float wt = rblBlendWeight(rho);\n",
    "                if (wt < 1.0)\n",
    "                {\n",
    "                    c = c*wt + (1.0 - wt); sn = sn*wt;\n",
    "                    float inv = 1.0/sqrt(c*c + sn*sn);\n",
    "                    c *= inv; sn *= inv;\n",
    "                }\n",
    "                n = nn*c + a*sn;\n",
    "                u = a*c - nn*sn;\n",
    "            }\n",
    "        }\n",
    "    }\n",
    "    else { n = axis; u = d; r = cross(u, n); }\n",
    "}\n",
    "\n",
    "#ifdef RBL_CASTER_ID\n",
    "// MurmurHash3's 32-bit finaliser (the CPU's rbl__mix32)\n",
    "uint rblMix32(uint h)\n",
    "{\n",
    "    h ^= h >> 16; h *= 0x85ebca6bu;\n",
    "    h ^= h >> 13; h *= 0xc2b2ae35u;\n",
    "    return h ^ (h >> 16);\n",
    "}\n",
    "\n",
    "// A billboard's caster identity: 16 bits mixed from the float bits of its pivot, size and origin (the\n",
    "// CPU's rbl__casterId; never 0, which marks Models), as two normalised bytes (high, low)\n",
    "vec2 rblCasterIdOf(vec3 pivot, vec4 sizeOrigin)\n",
    "{\n",
    "    uvec3 p = floatBitsToUint(pivot);\n",
    "    uvec4 s = floatBitsToUint(sizeOrigin);\n",
    "    uint h = rblMix32(rblMix32(rblMix32(rblMix32(rblMix32(rblMix32(rblMix32(p.x) ^ p.y) ^ p.z) ^ s.x) ^ s.y) ^ s.z) ^ s.w);\n",
    "    h = (h ^ (h >> 16)) & 0xffffu;\n",
    "    if (h == 0u) h = 1u;\n",
    "    return vec2(float(h >> 8), float(h & 255u))/255.0;\n",
    "}\n",
    "#endif\n",
    "\n",
    "// One corner (0 bottom-left, 1 bottom-right, 2 top-right, 3 top-left) of the instance's quad, given\n",
    "// its rotated frame: world position, texture coordinate, rounded normal and tangent\n",
    "void rblBillboardVertex(int corner, vec3 r, vec3 u, vec3 n, vec2 textureSize, float roundness,\n",
    "                        out vec3 position, out vec2 texCoord, out vec3 normal, out vec4 tangent)\n",
    "{\n",
    "    int flags = int(rblFlagBits + 0.5);\n",
    "    vec2 size = rblSizeOrigin.xy, origin = rblSizeOrigin.zw;\n",
    "    float sx = abs(size.x), sy = abs(size.y);\n",
    "    vec3 un = u;\n",
    "    rblNormalizeTo(u, un);\n",
    "    float ulen = length(u);\n",
    "    float cs = (corner == 1 || corner == 2)? 1.0 : 0.0;     // sprite-space s (right)\n",
    "    float ct = (corner < 2)? 1.0 : 0.0;                      // sprite-space t (down)\n",
    "    float x = (cs > 0.5)? sx - origin.x : -origin.x;\n",
    "    float y = (ct < 0.5)? sy*ulen - origin.y : -origin.y;\n",
    "    position = rblPivot.xyz + r*x + un*y;\n",
    "\n",
    "    vec4 src = rblSource;\n",
    "    if (src == vec4(0.0)) src = vec4(0.0, 0.0, textureSize);\n",
    "    bool flipU = (size.x < 0.0) != (src.z < 0.0);\n",
    "    bool flipV = (size.y < 0.0) != (src.w < 0.0);\n",
    "    bool rotated = (flags & 1) != 0;\n",
    "    float s = flipU? 1.0 - cs : cs;\n",
    "    float t = flipV? 1.0 - ct : ct;\n",
    "    vec2 frame = rotated? vec2(1.0 - t, s) : vec2(s, t);\n",
    "    texCoord = (src.xy + frame*abs(src.zw))/textureSize;\n",
    "\n",
    "    vec3 T, V;\n",
    "    if (!rotated) { T = flipU? -r : r; V = flipV? un : -un; }\n",
    "    else { T = flipV? -un : un; V = flipU? -r : r; }\n",
    "    float w = (dot(cross(n, T), V) < 0.0)? -1.0 : 1.0;\n",
    "\n",
    "    vec3 nv = n, tv = T;\n",
    "    float round = clamp(roundness, 0.0, 1.0);\n",
    "    if (round > 0.0)\n",
    "    {\n",
    "        float dx = (cs < 0.5)? -1.0 : 1.0;\n",
    "        float dy = ((flags & 2) != 0)? 0.0 : ((ct > 0.5)? -1.0 : 1.0);\n",
    "        rblNormalizeTo(n + (r*dx + un*dy)*round, nv);\n",
    "        if (!rblPerpendicular(T, nv, tv)) tv = T;\n",
    "    }\n",
    "    normal = nv;\n",
    "    tangent = vec4(tv, w);\n",
    "}\n",
    "\n",
    "#ifdef RBL_POLYGONS\n",
    "vec4 rblPolygonTexel(int i)\n",
    "{\n",
    "    int w = int(rblPolygon.y + 0.5);\n",
    "#ifdef RBL_SPRITE_BUFFER\n",
    "    return texelFetch(rblFrameTable, ivec2(i % w, i / w), 0);\n",
    "#else\n",
    "    return texelFetch(rblPolygonTable, ivec2(i % w, i / w), 0);\n",
    "#endif\n",
    "}\n",
    "\n",
    "// The instance's polygon as flat draws take it, or cut along the diagonal its quad's triangles meet\n",
    "// on (rbl__billboardCut): first corner texel, corner count\n",
    "vec2 rblPolygonCut()\n",
    "{\n",
    "    if (!(rblInstancing[1].w > 0.0)) return rblPolygonFlat;\n",
    "    bool flipU = (rblSizeOrigin.x < 0.0) != (rblSource.z < 0.0);\n",
    "    bool flipV = (rblSizeOrigin.y < 0.0) != (rblSource.w < 0.0);\n",
    "    bool rotated = (int(rblFlagBits + 0.5) & 1) != 0;\n",
    "    return ((flipU != flipV) != rotated)? rblPolygonSpan.xy : rblPolygonSpan.zw;\n",
    "}\n",
    "\n",
    "// Corner k of the instance's polygon (its cut from first) with the quad's fields there: position and\n",
    "// texture coordinate of the frame point, normal and tangent interpolated over the quad's triangle\n",
    "// (0, 1, 2) or (0, 2, 3) holding it, as the rasteriser would over the quad (rbl__expandQuad, the CPU\n",
    "// twin). A mirror turns the triangles over: corners 1 and 2 swap. Returns sprite (s right, t down).\n",
    "vec2 rblPolygonVertex(int first, int k, vec3 r, vec3 u, vec3 n, vec2 textureSize, float roundness,\n",
    "                      out vec3 position, out vec2 texCoord, out vec3 normal, out vec4 tangent)\n",
    "{\n",
    "    int flags = int(rblFlagBits + 0.5);\n",
    "    vec2 size = rblSizeOrigin.xy, origin = rblSizeOrigin.zw;\n",
    "    vec4 src = rblSource;\n",
    "    if (src == vec4(0.0)) src = vec4(0.0, 0.0, textureSize);\n",
    "    bool flipU = (size.x < 0.0) != (src.z < 0.0);\n",
    "    bool flipV = (size.y < 0.0) != (src.w < 0.0);\n",
    "    bool rotated = (flags & 1) != 0;\n",
    "    int m = k - (k/3)*3;\n",
    "    if (flipU != flipV) k += (m == 1)? 1 : ((m == 2)? -1 : 0);\n",
    "    vec4 texel = rblPolygonTexel(first + k/2);\n",
    "    vec2 ab = ((k & 1) != 0)? texel.zw : texel.xy;\n",
    "    float s = rotated? ab.y : ab.x, t = rotated? 1.0 - ab.x : ab.y;\n",
    "    if (flipU) s = 1.0 - s;\n",
    "    if (flipV) t = 1.0 - t;\n",
    "    float up = 1.0 - t;\n",
    "    vec3 un = u;\n",
    "    rblNormalizeTo(u, un);\n",
    "    float ulen = length(u), sx = abs(size.x), sy = abs(size.y);\n",
    "    float x = (-origin.x)*(1.0 - s) + (sx - origin.x)*s, y = (-origin.y)*(1.0 - up) + (sy*ulen - origin.y)*up;\n",
    "    position = rblPivot.xyz + r*x + un*y;\n",
    "    texCoord = (src.xy + ab*abs(src.zw))/textureSize;\n",
    "    vec3 pc, n1, n2;\n",
    "    vec2 tc;\n",
    "    vec4 g1, g2;\n",
    "    rblBillboardVertex(0, r, u, n, textureSize, roundness, pc, tc, normal, tangent);\n",
    "    if (clamp(roundness, 0.0, 1.0) > 0.0)\n",
    "    {\n",
    "        bool lower = s >= up;\n",
    "        vec3 w = lower? vec3(1.0 - s, s - up, up) : vec3(1.0 - up, s, up - s);\n",
    "        rblBillboardVertex(lower? 1 : 2, r, u, n, textureSize, roundness, pc, tc, n1, g1);\n",
    "        rblBillboardVertex(lower? 2 : 3, r, u, n, textureSize, roundness, pc, tc, n2, g2);\n",
    "        normal = normal*w.x + n1*w.y + n2*w.z;\n",
    "        tangent = vec4(tangent.xyz*w.x + g1.xyz*w.y + g2.xyz*w.z, tangent.w);\n",
    "    }\n",
    "    return vec2(s, t);\n",
    "}\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_CROSS_FADE\n",
    "// Texture coordinate of the corner at sprite (cs right, ct down) in frame src (all zero = the whole\n",
    "// texture), as rblBillboardVertex, and the frame's +U (T) and +V (V) in the quad's (right, up) plane\n",
    "vec2 rblFrameTexCoord(vec4 src, bool rotated, vec2 size, float cs, float ct, vec2 textureSize, out vec2 T, out vec2 V)\n",
    "{\n",
    "    if (src == vec4(0.0)) src = vec4(0.0, 0.0, textureSize);\n",
    "    bool flipU = (size.x < 0.0) != (src.z < 0.0);\n",
    "    bool flipV = (size.y < 0.0) != (src.w < 0.0);\n",
    "    float s = flipU? 1.0 - cs : cs;\n",
    "    float t = flipV? 1.0 - ct : ct;\n",
    "    if (!rotated) { T = vec2(flipU? -1.0 : 1.0, 0.0); V = vec2(0.0, flipV? 1.0 : -1.0); }\n",
    "    else { T = vec2(0.0, flipV? -1.0 : 1.0); V = vec2(flipU? -1.0 : 1.0, 0.0); }\n",
    "    return (src.xy + (rotated? vec2(1.0 - t, s) : vec2(s, t))*abs(src.zw))/textureSize;\n",
    "}\n",
    "\n",
    "// Position of picture point p (quad fractions, top-left origin) in clip rectangle c (x, y, width,\n",
    "// height; zero size = the whole quad); an axis c covers whole is 0.5 (as the CPU's rbl__fadeClipLocal)\n",
    "vec2 rblFadeClipLocal(vec4 c, vec2 p)\n",
    "{\n",
    "    if (!((c.z > 0.0) && (c.w > 0.0))) return vec2(0.5);\n",
    "    vec2 l = (p - c.xy)/c.zw;\n",
    "    if ((c.x <= 0.0) && (c.x + c.z >= 1.0)) l.x = 0.5;\n",
    "    if ((c.y <= 0.0) && (c.y + c.w >= 1.0)) l.y = 0.5;\n",
    "    return l;\n",
    "}\n",
    "\n",
    "// The second frame's axes against the first's: swap (its +U along the first's V) + 2 negT + 4 negV\n",
    "float rblFadeCode(vec2 t1, vec2 v1, vec2 t2, vec2 v2)\n",
    "{\n",
    "    float x = dot(t2, v1);\n",
    "    bool swapAxes = x != 0.0;\n",
    "    float negT = ((swapAxes? x : dot(t2, t1)) < 0.0)? 2.0 : 0.0;\n",
    "    float negV = ((swapAxes? dot(v2, t1) : dot(v2, v1)) < 0.0)? 4.0 : 0.0;\n",
    "    return (swapAxes? 1.0 : 0.0) + negT + negV;\n",
    "}\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_SPRITE_BUFFER\n",
    "// Texel i of the frame table (rows of rblInstancing[7].z texels)\n",
    "vec4 rblTable(int i)\n",
    "{\n",
    "    int w = int(rblInstancing[7].z + 0.5);\n",
    "    return texelFetch(rblFrameTable, ivec2(i % w, i / w), 0);\n",
    "}\n",
    "\n",
    "// An IEEE half float from its 16 bits (the CPU writes finite, non-negative speeds only)\n",
    "float rblHalfBits(uint h)\n",
    "{\n",
    "    uint e = (h >> 10) & 31u, m = h & 1023u;\n",
    "    float v = (e == 0u)? float(m)*exp2(-24.0) : exp2(float(int(e) - 15))*(1.0 + float(m)*(1.0/1024.0));\n",
    "    return ((h & 0x8000u) != 0u)? -v : v;\n",
    "}\n",
    "\n",
    "// The frame tag t shows local seconds into its play, the frame after it and the weight time /\n",
    "// duration (RblSpriteBlend's): the CPU's RblUpdateSprite over loops passes (0 = forever), with the\n",
    "// period's frames as a timeline found by bisection\n",
    "void rblSpriteFrame(int t, int loops, float local, out int frame, out int next, out float weight)\n",
    "{\n",
    "    int base = 3*int(rblInstancing[7].w + 0.5) + 2*(t + 1);   // tag -1 (every frame) is the first row\n",
    "    vec4 row = rblTable(base), ends = rblTable(base + 1);\n",
    "    int first = int(row.x + 0.5), count = int(row.y + 0.5);\n",
    "    float period = row.z;\n",
    "    if (loops < 0) loops = int(ends.z + 0.5);                  // the tag's repeat (0 = forever)\n",
    "    if (loops > 0)\n",
    "    {\n",
    "        // A pingpong pass ends on a turn frame: pass 2m + 1 at m periods + the first pass, pass 2m\n",
    "        // at m periods + the first frame (ends.w; 0: one pass per period)\n",
    "        float end = (ends.w > 0.0)? float(loops/2)*period + (((loops & 1) != 0)? row.w : ends.w) : float(loops)*period;\n",
    "        int last = int((((loops & 1) != 0)? ends.x : ends.y) + 0.5);\n",
    "        if (local >= end - rblTable(3*last + 2).x) { frame = last; next = last; weight = 0.0; return; }\n",
    "    }\n",
    "    float tp = local - floor(local/period)*period;\n",
    "    if (!(tp < period) || (tp < 0.0)) tp = 0.0;\n",
    "    int lo = 0, hi = count;                                     // entries [lo, hi): start(lo) <= tp\n",
    "    for (int i = 0; (i < 16) && (hi - lo > 1); i++)\n",
    "    {\n",
    "        int mid = (lo + hi)/2;\n",
    "        if (rblTable(first + mid).y <= tp) lo = mid; else hi = mid;\n",
    "    }\n",
    "    vec4 entry = rblTable(first + lo);\n",
    "    frame = int(entry.x + 0.5);\n",
    "    next = int(rblTable(first + ((lo + 1 < count)? lo + 1 : 0)).x + 0.5);\n",
    "    weight = clamp((tp - entry.y)/rblTable(3*frame + 2).x, 0.0, 1.0);\n",
    "}\n",
    "\n",
    "// A resident sprite into the instance globals: its frame (animated on the clock rblInstancing[7].y)\n",
    "// from the table, the quad scaled from the frame's, flips about the pivot\n",
    "void rblReadSprite()\n",
    "{\n",
    "    vec4 word = rblInstanceSource;                              // rotation, frame, speed bits, mode\n",
    "    uint mode = uint(word.w + 0.5);\n",
    "    int frame = int(word.y + 0.5), next = frame;\n",
    "    float weight = 0.0;\n",
    "    if ((mode & 8u) != 0u)\n",
    "    {\n",
    "        int tag = (frame == 65535)? -1 : frame;\n",
    "        int loops = int(mode >> 8);\n",
    "        loops = (loops == 0)? -1 : ((loops == 255)? 0 : loops);\n",
    "        float local = max((rblInstancing[7].y - rblInstanceSize.x)*rblHalfBits(uint(word.z + 0.5)), 0.0);\n",
    "        rblSpriteFrame(tag, loops, local, frame, next, weight);\n",
    "    }\n",
    "    vec4 quad = rblTable(3*frame + 1)*rblInstancePosition.w;   // size, origin\n",
    "    if ((mode & 1u) != 0u) quad.xz = vec2(-quad.x, quad.x - quad.z);\n",
    "    if ((mode & 2u) != 0u) quad.yw = vec2(-quad.y, quad.y - quad.w);\n",
    "    rblPivot = vec4(rblInstancePosition.xyz, word.x*(360.0/65536.0));\n",
    "    rblSizeOrigin = quad;\n",
    "    rblSource = rblTable(3*frame);\n",
    "    vec4 frameBits = rblTable(3*frame + 2);\n",
    "    rblFlagBits = frameBits.y + (((mode & 4u) != 0u)? 2.0 : 0.0);\n",
    "#ifdef RBL_POLYGONS\n",
    "    rblPolygonal = frameBits.w > 0.5;\n",
    "    rblPolygonSpan = rblPolygonal? rblTable(int(frameBits.z + 0.5)) : vec4(0.0);\n",
    "    rblPolygonFlat = rblPolygonal? rblTable(int(frameBits.z + 0.5) + 1).xy : vec2(0.0);\n",
    "#endif\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    rblFadeSource = rblTable(3*next);\n",
    "    rblFadeFlagBits = rblTable(3*next + 2).y;\n",
    "    rblFadeWeight = weight;\n",
    "    rblFadeClip0 = vec4(0.0); rblFadeClip1 = vec4(0.0);\n",
    "#endif\n",
    "}\n",
    "#endif\n",
    "\n",
    "void main()\n",
    "{\n",
    "#ifdef RBL_SPRITE_BUFFER\n",
    "    rblReadSprite();\n",
    "#elif defined(RBL_BATCH_RECORD)\n",
    "    rblPivot = vec4(rblRecordPosition, rblRecordRotation); rblSizeOrigin = rblRecordSizeOrigin; rblSource = rblRecordSource; rblFlagBits = rblRecordFlags;\n",
    "#else\n",
    "    rblPivot = rblInstancePosition; rblSizeOrigin = rblInstanceSize; rblSource = rblInstanceSource; rblFlagBits = rblInstanceFlags;\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    rblFadeSource = rblInstanceFadeSource; rblFadeWeight = rblInstanceFadeWeight; rblFadeFlagBits = rblInstanceFadeFlags;\n",
    "    rblFadeClip0 = rblInstanceFadeClip; rblFadeClip1 = rblInstanceFadeClip2;\n",
    "#endif\n",
    "#ifdef RBL_POLYGONS\n",
    "    // The handle in flags bits 4..23 (flags from 2^24 up hold none: the float is exact below it)\n",
    "    uint handle = (rblFlagBits < 16777216.0)? (uint(rblFlagBits + 0.5) >> 4) & 0xFFFFFu : 0u;\n",
    "    rblPolygonal = handle != 0u;\n",
    "    int header = 2*(int(handle) - int(rblPolygon.z + 0.5));\n",
    "    rblPolygonSpan = rblPolygonal? rblPolygonTexel(header) : vec4(0.0);\n",
    "    rblPolygonFlat = rblPolygonal? rblPolygonTexel(header + 1).xy : vec2(0.0);\n",
    "#endif\n",
    "#endif\n",
    "#ifdef RBL_POLYGONS\n",
    "    // Past the instance's corners (a quad's 6, or its polygon's): one point outside the view, so the\n",
    "    // padding triangles have no area\n",
    "    vec2 cut = rblPolygonal? rblPolygonCut() : vec2(0.0, 6.0);\n",
    "    if (gl_VertexID >= int(cut.y + 0.5))\n",
    "    {\n",
    "        fragPosition = vec3(0.0); fragTexCoord = vec2(0.0); fragColor = vec4(0.0); fragNormal = vec3(0.0, 0.0, 1.0); fragTangent = vec4(1.0, 0.0, 0.0, 1.0);\n",
    "        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n",
    "        return;\n",
    "    }\n",
    "#endif\n",
    "    const int cornerOf[6] = int[6](0, 1, 2, 0, 2, 3);\n",
    "    vec3 eye = rblInstancing[0].xyz;\n",
    "    int code = int(rblInstancing[0].w + 0.5);\n",
    "    vec3 facingUp = rblInstancing[4].xyz, facingAxis = rblInstancing[5].xyz;\n",
    "    float roundness = rblInstancing[1].w;\n",
    "#ifdef RBL_BATCH_RECORD\n",
    "    vec4 tintIn = rblRecordTint;\n",
    "    int facing = int(rblRecordFacing + 0.5);\n",
    "    if (((code & 16) != 0) && (facing == 0)) facing = 1;\n",
    "    code = facing + (code & 8);\n",
    "    facingUp = rblRecordUp; facingAxis = rblRecordAxis; roundness = rblRecordRoundness;\n",
    "#else\n",
    "    vec4 tintIn = rblInstanceTint;\n",
    "#endif\n",
    "    vec3 r, u, n;\n",
    "    rblFacingBasis(code, rblPivot.xyz, eye, rblInstancing[5].w, rblInstancing[1].xyz, rblInstancing[2].xyz,\n",
    "                   rblInstancing[3].xyz, facingUp, facingAxis, rblInstancing[4].w, rblInstancing[6], r, u, n);\n",
    "    // A tilted AXIS caster turns about its lowest edge, moving to mid-height as the light nears the\n",
    "    // axis (rbl__billboardVertices)\n",
    "    vec3 shift = vec3(0.0);\n",
    "    vec2 sc = vec2(0.0, 1.0);\n",
    "    if (rblPivot.w != 0.0) sc = rblSinCosDeg(rblPivot.w);\n",
    "    if (((code & 3) == 2) && (rblInstancing[4].w > 0.0))\n",
    "    {\n",
    "        vec3 a = vec3(0.0, 1.0, 0.0), l = a;\n",
    "        if (dot(facingAxis, facingAxis) > 1e-24) rblNormalizeTo(facingAxis, a);\n",
    "        vec3 d = a - u;\n",
    "        vec4 light = rblInstancing[6];\n",
    "        if ((dot(d, d) > 0.0) && rblNormalizeTo(light.xyz - rblPivot.xyz*light.w, l))\n",
    "        {\n",
    "            float x0 = -rblSizeOrigin.z, x1 = abs(rblSizeOrigin.x) - rblSizeOrigin.z;\n",
    "            float y0 = -rblSizeOrigin.w, y1 = abs(rblSizeOrigin.y) - rblSizeOrigin.w;\n",
    "            vec4 e = vec4(sc.x*x0 + sc.y*y0, sc.x*x1 + sc.y*y0, sc.x*x1 + sc.y*y1, sc.x*x0 + sc.y*y1);\n",
    "            float lo = min(min(e.x, e.y), min(e.z, e.w)), hi = max(max(e.x, e.y), max(e.z, e.w));\n",
    "            float t = clamp((abs(dot(l, a)) - 0.8660254)*(1.0/(1.0 - 0.8660254)), 0.0, 1.0);\n",
    "            shift = d*(lo + 0.5*(hi - lo)*(t*t*(3.0 - 2.0*t)));\n",
    "        }\n",
    "    }\n",
    "    // Rotate the frame around the normal (raylib rotates the corners; same result)\n",
    "    if (rblPivot.w != 0.0)\n",
    "    {\n",
    "        vec3 nr = cross(n, r), nu = cross(n, u);\n",
    "        r = r*sc.y + nr*sc.x;\n",
    "        u = u*sc.y + nu*sc.x;\n",
    "    }\n",
    "    vec3 p;\n",
    "#ifdef RBL_POLYGONS\n",
    "    vec2 polygonPoint = vec2(-1.0);\n",
    "    if (rblPolygonal)\n",
    "        polygonPoint = rblPolygonVertex(int(cut.x + 0.5), gl_VertexID, r, u, n, vec2(rblInstancing[2].w, rblInstancing[3].w), roundness,\n",
    "                                        p, fragTexCoord, fragNormal, fragTangent);\n",
    "    else\n",
    "#endif\n",
    "    rblBillboardVertex(cornerOf[gl_VertexID % 6], r, u, n, vec2(rblInstancing[2].w, rblInstancing[3].w), roundness,\n",
    "                       p, fragTexCoord, fragNormal, fragTangent);\n",
    "    p += shift;\n",
    "    fragPosition = p;\n",
    "#ifdef RBL_CASTER_ID\n",
    "    fragCasterId = rblCasterIdOf(rblPivot.xyz, rblSizeOrigin);\n",
    "#endif\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    int corner = cornerOf[gl_VertexID % 6];\n",
    "    float cs = (corner == 1 || corner == 2)? 1.0 : 0.0, ct = (corner < 2)? 1.0 : 0.0;\n",
    "#ifdef RBL_POLYGONS\n",
    "    if (polygonPoint.x >= 0.0) { cs = polygonPoint.x; ct = polygonPoint.y; }\n",
    "#endif\n",
    "    vec2 textureSize = vec2(rblInstancing[2].w, rblInstancing[3].w), t1, v1, t2, v2;\n",
    "    rblFrameTexCoord(rblSource, (int(rblFlagBits + 0.5) & 1) != 0, rblSizeOrigin.xy, cs, ct, textureSize, t1, v1);\n",
    "    fragTexCoord2 = rblFrameTexCoord(rblFadeSource, (int(rblFadeFlagBits + 0.5) & 1) != 0, rblSizeOrigin.xy, cs, ct, textureSize, t2, v2);\n",
    "    fragFade = vec2(rblFadeWeight, rblFadeCode(t1, v1, t2, v2));\n",
    "    // Clip rectangles are in the picture: a mirrored quad mirrors them with it\n",
    "    vec2 picture = vec2((rblSizeOrigin.x < 0.0)? 1.0 - cs : cs, (rblSizeOrigin.y < 0.0)? 1.0 - ct : ct);\n",
    "    fragFadeClip = vec4(rblFadeClipLocal(rblFadeClip0, picture), rblFadeClipLocal(rblFadeClip1, picture));\n",
    "#endif\n",
    "    vec4 tint = (tintIn == vec4(0.0))? vec4(1.0) : tintIn;\n",
    "    fragColor = vec4(rblSrgbToLinear(tint.rgb), tint.a);       // sRGB like every raylib Color: decoded once per vertex\n",
    "#ifdef RBL_VIEW_VECTOR\n",
    "    fragEye = eye;\n",
    "    fragViewAxis = vec4(rblInstancing[3].xyz, rblInstancing[5].w);\n",
    "#endif\n",
    "    gl_Position = mvp*vec4(p, 1.0);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_material[] = {
    "// Material: fragment inputs, the material's maps and per-draw values, alpha test, normal-map decode\n",
    "// and tangent frame -> RblShadingPoint. Shared by every pass that shades a material (lit.fs.glsl,\n",
    "// gbuffer.fs.glsl, shadow_caster.fs.glsl). Colour (albedo, emissive, vertex tint, colDiffuse) is sRGB\n",
    "// and decoded to linear light; data maps (normal, specular/roughness, occlusion) are linear.\n",
    "// Material defines (absent maps are never declared, so never sampled):\n",
    "//   RBL_NORMAL_ENCODING e    0 none, 1 hemi-octahedral RG, 2 XY RG (+Z rebuilt), 3 plain RGB map\n",
    "//   RBL_SPECULAR             material texture B: Blinn-Phong specular intensity / GGX roughness\n",
    "//   RBL_OCCLUSION            material texture A holds ambient occlusion\n",
    "//   RBL_EMISSIVE e           0 none, 1 mask (texture5.r x albedo), 2 sRGB colour (texture5.rgb)\n",
    "//   RBL_PREMULTIPLIED_ALPHA  albedo texels hold colour x alpha (libGDX pma): the filtered texel is\n",
    "//                            divided by its alpha before decoding (the alpha-weighted mean of its\n",
    "//                            neighbours' colours, no dark fringe); lit and written as straight alpha\n",
    "//   RBL_VIEW_VECTOR          the eye position is needed (specular BRDF or fog)\n",
    "//   RBL_CASTER_ID            the billboard's caster identity arrives (receivers, casters, G-buffer)\n",
    "//   RBL_CROSS_FADE           a second atlas frame mixed in (RblLitShaderDesc.crossFade): every map\n",
    "//                            is fetched at both texture coordinates. What is mixed: colour in linear\n",
    "//                            light weighted by coverage (alpha), as the mips average; alpha linearly,\n",
    "//                            the cutoff applies to the mixed alpha; the normal as a world vector (each\n",
    "//                            fetch decoded in its own frame's tangent axes), then renormalised;\n",
    "//                            specular, occlusion and emission with the colour's coverage weight\n",
    "//   RBL_TRANSMISSION, RBL_THICKNESS_CHANNEL   the card lets light through (transmission.glsl)\n",
    "//   RBL_RELIEF_STEPS, RBL_HEIGHT_CHANNEL      relief self-shadow (relief.glsl): the tangent frame kept for the lights\n",
    "#include \"surface.glsl\"\n",
    "#include \"transmission.glsl\"\n",
    "#include \"relief.glsl\"\n",
    "\n",
    "RBL_VARYING vec3 fragPosition;\n",
    "RBL_VARYING vec2 fragTexCoord;\n",
    "RBL_VARYING vec4 fragColor;              // vertex colour, already linear (decoded in the vertex stage)\n",
    "RBL_VARYING vec3 fragNormal;\n",
    "RBL_VARYING vec4 fragTangent;\n",
    "#ifdef RBL_VIEW_VECTOR\n",
    "RBL_FLAT RBL_VARYING vec3 fragEye;           // camera position (from matView in the vertex stage)\n",
    "RBL_FLAT RBL_VARYING vec4 fragViewAxis;      // camera back direction, w 1 orthographic (rblViewVector)\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_CASTER_ID\n",
    "RBL_FLAT RBL_VARYING vec2 fragCasterId;  // the billboard's caster identity (lit.vs.glsl), 0 for Models\n",
    "#endif\n",
    "\n",
    "#ifdef RBL_CROSS_FADE\n",
    "RBL_VARYING vec2 fragTexCoord2;          // the second frame's texture coordinate\n",
    "RBL_FLAT RBL_VARYING vec2 fragFade;      // x weight 0..1 of the second frame, y its tangent axes (rblFadeAxes)\n",
    "// Each frame's position within its own trimmed rectangle (xy the first, zw the second): inside is\n",
    "// 0..1 on both axes; an axis the frame covers whole is a constant 0.5 (never clipped by rounding)\n",
    "RBL_VARYING vec4 fragFadeClip;\n",
    "// Exact ends: weight 0 is the first frame and 1 the second, bit for bit (no mix rounding)\n",
    "#define rblFadeMix(a, b, w) (((w) <= 0.0)? (a) : (((w) >= 1.0)? (b) : mix((a), (b), (w))))\n",
    "#endif\n",
    "\n",
    "uniform sampler2D texture0;     // albedo (sRGB)\n",
    "#if (RBL_NORMAL_ENCODING > 0) || defined(RBL_SPECULAR) || defined(RBL_OCCLUSION) || defined(RBL_HEIGHT_CHANNEL) || defined(RBL_THICKNESS_CHANNEL)\n",
    "#define RBL_MATERIAL_TEXTURE\n",
    "uniform sampler2D texture2;     // packed material (MATERIAL_MAP_NORMAL slot): RG normal, B specular, A occlusion\n",
    "#endif\n",
    "#if RBL_EMISSIVE > 0\n",
    "uniform sampler2D texture5;     // emissive (MATERIAL_MAP_EMISSION slot)\n",
    "uniform float rblEmissiveIntensity;\n",
    "#endif\n",
    "uniform vec3 rblEmissiveColor;  // constant emission (linear, intensity applied; the material's EMISSION colour)\n",
    "#if RBL_BRDF == 1\n",
    "uniform vec4 rblSpecularColor;  // rgb linear specular colour x intensity, a shininess\n",
    "#elif RBL_BRDF == 2\n",
    "uniform vec2 rblRoughMetal;     // perceptual roughness (when no map), metalness\n",
    "#endif\n",
    "uniform vec4 colDiffuse;        // sRGB, as raylib sets it\n",
    "uniform vec2 rblAlphaCutoff;   // kept from x (the material's cutoff) up to, not including, y (a hybrid batch's solid alpha; 2 otherwise)\n",
    "\n",
    "// Tangent-space normal from the material texture; the exact mirror of RblDecodeNormal() on the CPU\n",
    "// (a decoded vector shorter than 1/64 is quantisation noise around zero: the flat normal)\n",
    "vec3 rblDecodedUnit(vec3 e)\n",
    "{\n",
    "    return (dot(e, e) < 1.0/4096.0)? vec3(0.0, 0.0, 1.0) : normalize(e);\n",
    "}\n",
    "\n",
    "vec3 rblDecodeNormal(vec4 m)\n",
    "{\n",
    "#if RBL_NORMAL_ENCODING == 1\n",
    "    vec2 e = m.rg*2.0 - 1.0;                                // hemi-octahedral, stored rotated 45 degrees\n",
    "    vec2 p = vec2(e.x + e.y, e.x - e.y)*0.5;\n",
    "    return rblDecodedUnit(vec3(p, 1.0 - max(abs(e.x), abs(e.y))));     // = 1-|p.x|-|p.y|, never negative\n",
    "#elif RBL_NORMAL_ENCODING == 2\n",
    "    vec2 e = m.rg*2.0 - 1.0;                                // X and Y, Z rebuilt\n",
    "    return rblDecodedUnit(vec3(e, sqrt(max(0.0, 1.0 - dot(e, e)))));\n",
    "#elif RBL_NORMAL_ENCODING == 3\n",
    "    return rblDecodedUnit(m.rgb*2.0 - 1.0);                 // plain RGB map\n",
    "#else\n",
    "    return vec3(0.0, 0.0, 1.0);\n",
    "#endif\n",
    "}\n",
    "\n",
    "#ifdef RBL_CROSS_FADE\n",
    "// The second frame's tangent axes from the first's (t = +U, b = +V, both world): code = swap + 2 negT\n",
    "// + 4 negV, where swap says its +U runs along the first's V (a frame stored rotated differently)\n",
    "void rblFadeAxes(float code, vec3 t, vec3 b, out vec3 t2, out vec3 b2)\n",
    "{\n",
    "    float c = floor(code + 0.5);                // interpolated (GLSL 1.x has no flat): round\n",
    "    bool swapAxes = mod(c, 2.0) > 0.5;\n",
    "    t2 = (swapAxes? b : t)*((mod(floor(c*0.5), 2.0) > 0.5)? -1.0 : 1.0);\n",
    "    b2 = (swapAxes? t : b)*((c > 3.5)? -1.0 : 1.0);\n",
    "}\n",
    "\n",
    "// Weight of the second frame's surface values: its share of the mixed coverage, so the colour and\n",
    "// data of a transparent texel (gutter or background) never bleed in\n",
    "// 1 inside a frame's trimmed rectangle, 0 outside (there it is transparent: no colour, no normal)\n",
    "float rblFadeInside(vec2 local)\n",
    "{\n",
    "    return ((local.x >= 0.0) && (local.x <= 1.0) && (local.y >= 0.0) && (local.y <= 1.0))? 1.0 : 0.0;\n",
    "}\n",
    "\n",
    "float rblFadeCoverage(float w, float a1, float a2)\n",
    "{\n",
    "    if (w <= 0.0) return 0.0;\n",
    "    if (w >= 1.0) return 1.0;\n",
    "    float a = mix(a1, a2, w);\n",
    "    return (a > 0.0)? clamp(w*a2/a, 0.0, 1.0) : w;\n",
    "}\n",
    "#endif\n",
    "\n",
    "// A filtered albedo texel as straight (not premultiplied) sRGB colour and alpha\n",
    "vec4 rblStraightAlpha(vec4 texel)\n",
    "{\n",
    "#ifdef RBL_PREMULTIPLIED_ALPHA\n",
    "    return vec4((texel.a > 0.0)? min(texel.rgb/texel.a, vec3(1.0)) : vec3(0.0), texel.a);\n",
    "#else\n",
    "    return texel;\n",
    "#endif\n",
    "}\n",
    "\n",
    "// The material at this fragment: discards below the alpha cutoff; alpha, emission and the\n",
    "// tangent-space normal (debug views) come back through the out parameters\n",
    "RblShadingPoint rblMaterialSurface(out float alpha, out vec3 emission, out vec3 tangentNormal)\n",
    "{\n",
    "    // The surface as rasterised (what a shadow map holds): the card's plane, not the rounded or\n",
    "    // normal-mapped normal that shades it; without derivatives (ES 2 lacking the extension) the\n",
    "    // interpolated vertex normal. Taken before any discard (derivatives need the whole quad)\n",
    "#ifdef RBL_DERIVATIVES\n",
    "    vec3 face = rblSafeNormalize(cross(dFdx(fragPosition), dFdy(fragPosition)), rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0)));\n",
    "#else\n",
    "    vec3 face = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));\n",
    "#endif\n",
    "    vec4 texel = rblStraightAlpha(texture(texture0, fragTexCoord));\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    // Both fetches outside any branch: implicit derivatives (mips) need every pixel of a quad to sample\n",
    "    vec4 texel2 = rblStraightAlpha(texture(texture0, fragTexCoord2));\n",
    "    float fade = fragFade.x;\n",
    "    float inside1 = rblFadeInside(fragFadeClip.xy), inside2 = rblFadeInside(fragFadeClip.zw);\n",
    "    // Outside the frame shown alone (or both) there is no fragment, as with that frame's own quad\n",
    "    if ((inside1 + inside2 == 0.0) || ((fade <= 0.0) && (inside1 == 0.0)) || ((fade >= 1.0) && (inside2 == 0.0))) discard;\n",
    "    texel *= inside1;\n",
    "    texel2 *= inside2;\n",
    "    float cover = rblFadeCoverage(fade, texel.a, texel2.a);\n",
    "    texel = vec4(rblFadeMix(rblSrgbToLinear(texel.rgb), rblSrgbToLinear(texel2.rgb), cover), rblFadeMix(texel.a, texel2.a, fade));\n",
    "    vec4 albedo = vec4(texel.rgb*rblSrgbToLinear(colDiffuse.rgb)*fragColor.rgb, texel.a*colDiffuse.a*fragColor.a);\n",
    "#else\n",
    "    vec4 albedo = vec4(rblSrgbToLinear(texel.rgb)*rblSrgbToLinear(colDiffuse.rgb)*fragColor.rgb, texel.a*colDiffuse.a*fragColor.a);\n",
    "#endif\n",
    "    if ((albedo.a < rblAlphaCutoff.x) || (albedo.a >= rblAlphaCutoff.y)) discard;\n",
    "\n",
    "    vec3 n = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));\n",
    "    // Two-sided: a back face (a card seen from behind, an open mesh from inside) is shaded on the\n",
    "    // side the viewer sees, as the card's mirror image through its plane: the normal flips, the\n",
    "    // normal map's tangent components stay (a relief reads raised from both sides). The winding says\n",
    "    // which side is seen for any projection, where dot(N, view) would also flip the interpolated\n",
    "    // normals of front faces near a smooth silhouette.\n",
    "    float side = gl_FrontFacing? 1.0 : -1.0;\n",
    "#ifdef RBL_MATERIAL_TEXTURE\n",
    "    vec4 material = texture(texture2, fragTexCoord);\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    vec4 material2 = texture(texture2, fragTexCoord2);\n",
    "#endif\n",
    "#endif\n",
    "    tangentNormal = vec3(0.0, 0.0, 1.0);\n",
    "#if (RBL_NORMAL_ENCODING > 0) || defined(RBL_RELIEF_STEPS)\n",
    "    // Re-orthogonalise the interpolated tangent; cross(N,T)*w is the +V direction (raylib's\n",
    "    // GenMeshTangents convention), and +V runs down the image, so the map's +Y is -B.\n",
    "    vec3 t = fragTangent.xyz - n*dot(n, fragTangent.xyz);\n",
    "    vec3 anyPerp = (abs(n.z) < 0.9)? vec3(-n.y, n.x, 0.0) : vec3(0.0, -n.z, n.y);\n",
    "    t = rblSafeNormalize(t, rblSafeNormalize(anyPerp, vec3(1.0, 0.0, 0.0)));\n",
    "    vec3 b = cross(n, t)*((fragTangent.w < 0.0)? -1.0 : 1.0);\n",
    "#ifdef RBL_RELIEF_STEPS\n",
    "    rblReliefSetup(texture2, fragTexCoord, t, b, n*side);\n",
    "#endif\n",
    "#endif\n",
    "#if RBL_NORMAL_ENCODING > 0\n",
    "    tangentNormal = rblDecodeNormal(material);\n",
    "#ifdef RBL_CROSS_FADE\n",
    "    // Each fetch in its own frame's axes, mixed as world vectors, renormalised (opposite normals\n",
    "    // cancel to the geometric one); the debug view gets the mix in the first frame's axes\n",
    "    vec3 n1 = t*tangentNormal.x - b*tangentNormal.y + n*(side*tangentNormal.z);\n",
    "    vec3 t2, b2;\n",
    "    rblFadeAxes(fragFade.y, t, b, t2, b2);\n",
    "    vec3 m2 = rblDecodeNormal(material2);\n",
    "    vec3 n2 = t2*m2.x - b2*m2.y + n*(side*m2.z);\n",
    "    vec3 nm = rblFadeMix(n1, n2, cover);\n",
    "    if (cover > 0.0)\n",
    "    {\n",
    "        nm = rblSafeNormalize(nm, n*side);\n",
    "        tangentNormal = vec3(dot(nm, t), -dot(nm, b), side*dot(nm, n));\n",
    "    }\n",
    "    n = rblSafeNormalize(nm, n*side);\n",
    "#else\n",
    "    n = rblSafeNormalize(t*tangentNormal.x - b*tangentNormal.y + n*(side*tangentNormal.z), n*side);\n",
    "#endif\n",
    "#else\n",
    "    n *= side;\n",
    "#endif\n",
    "#if defined(RBL_CROSS_FADE) && defined(RBL_MATERIAL_TEXTURE)\n",
    "    material = rblFadeMix(material, material2, cover);       // specular and occlusion (the normal is done)\n",
    "#endif\n",
    "    RblShadingPoint sp;\n",
    "    sp.position = fragPosition;\n",
    "    sp.normal = n;\n",
    "    sp.albedo = albedo.rgb;\n",
    "    sp.specular = 1.0;\n",
    "    sp.roughness = 0.5;\n",
    "    sp.specularColor = vec3(1.0);\n",
    "    sp.shininess = 1.0;\n",
    "    sp.metalness = 0.0;\n",
    "    sp.face = face;\n",
    "#ifdef RBL_CASTER_ID\n",
    "    sp.caster = fragCasterId;\n",
    "#else\n",
    "    sp.caster = vec2(0.0);\n",
    "#endif\n",
    "#if RBL_BRDF == 1\n",
    "    sp.specularColor = rblSpecularColor.rgb;\n",
    "    sp.shininess = rblSpecularColor.a;\n",
    "#elif RBL_BRDF == 2\n",
    "    sp.roughness = rblRoughMetal.x;\n",
    "    sp.metalness = rblRoughMetal.y;\n",
    "#endif\n",
    "#if defined(RBL_SPECULAR) && (RBL_BRDF == 2)\n",
    "    sp.roughness = material.b;             // a GGX material texture holds roughness in B\n",
    "#elif defined(RBL_SPECULAR)\n",
    "    sp.specular = material.b;\n",
    "#endif\n",
    "    sp.occlusion = 1.0;\n",
    "#ifdef RBL_OCCLUSION\n",
    "    sp.occlusion = material.a;\n",
    "#endif\n",
    "    sp.transmission = 0.0;\n",
    "#ifdef RBL_TRANSMISSION\n",
    "    sp.transmission = rblTransmission;\n",
    "#ifdef RBL_THICKNESS_CHANNEL\n",
    "    sp.transmission *= 1.0 - material[RBL_THICKNESS_CHANNEL - 1];\n",
    "#endif\n",
    "#endif\n",
    "    alpha = albedo.a;\n",
    "    emission = vec3(0.0);\n",
    "#if defined(RBL_CROSS_FADE) && (RBL_EMISSIVE == 1)\n",
    "    emission += albedo.rgb*rblFadeMix(texture(texture5, fragTexCoord).r*inside1, texture(texture5, fragTexCoord2).r*inside2, cover)*rblEmissiveIntensity;\n",
    "#elif defined(RBL_CROSS_FADE) && (RBL_EMISSIVE == 2)\n",
    "    emission += rblFadeMix(rblSrgbToLinear(texture(texture5, fragTexCoord).rgb)*inside1, rblSrgbToLinear(texture(texture5, fragTexCoord2).rgb)*inside2, cover)*rblEmissiveIntensity;\n",
    "#elif RBL_EMISSIVE == 1\n",
    "    emission += albedo.rgb*texture(texture5, fragTexCoord).r*rblEmissiveIntensity;\n",
    "#elif RBL_EMISSIVE == 2\n",
    "    emission += rblSrgbToLinear(texture(texture5, fragTexCoord).rgb)*rblEmissiveIntensity;\n",
    "#endif\n",
    "    emission += rblEmissiveColor;\n",
    "    return sp;\n",
    "}\n",
    "\n",
    "#ifdef RBL_RELIEF_STEPS\n",
    "// The relief's light factor toward unit l at the point rblMaterialSurface last decoded (lights.glsl)\n",
    "float rblReliefShadow(vec3 l)\n",
    "{\n",
    "    return rblReliefMarch(texture2, l);\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_output[] = {
    "// Output: fog, half-float clamp, exposure, tonemap and the display encoding, in that order (the\n",
    "// scene's fog and exposure; the program's compiled tonemap and encoding).\n",
    "//   RBL_FOG f                 0 none, 1 linear, 2 exp, 3 exp2 (by rblViewDistance: to the eye, or\n",
    "//                             along the view axis for an orthographic camera)\n",
    "//   RBL_TONEMAP t             0 none, 1 Reinhard, 2 ACES fit (Narkowicz 2015)\n",
    "//   RBL_GAMMA g               encode with pow(1/g) instead of the exact sRGB curve\n",
    "//   RBL_LINEAR_OUTPUT         keep linear light (float targets)\n",
    "#include \"common.glsl\"\n",
    "\n",
    "#if RBL_FOG > 0\n",
    "uniform vec4 rblFog;                        // rgb linear colour, a: density (exp/exp2) or 1/(end - start) (linear)\n",
    "uniform float rblFogStart;                  // linear fog: distance where it begins\n",
    "#endif\n",
    "uniform float rblExposure;                  // the scene's exposure\n",
    "\n",
    "// Fog at view distance d, exposure, tonemap and the display encoding, in that order. linearOut keeps\n",
    "// linear light (clamped to half-float range) for float targets.\n",
    "vec3 rblFinish(vec3 color, float d)\n",
    "{\n",
    "#if RBL_FOG > 0\n",
    "#if RBL_FOG == 1\n",
    "    float visible = clamp(1.0 - (d - rblFogStart)*rblFog.a, 0.0, 1.0);\n",
    "#elif RBL_FOG == 2\n",
    "    float visible = exp(-rblFog.a*d);\n",
    "#else\n",
    "    float visible = exp(-(rblFog.a*d)*(rblFog.a*d));\n",
    "#endif\n",
    "    color = mix(rblFog.rgb, color, visible);\n",
    "#endif\n",
    "    color = clamp(color, 0.0, RBL_HALF_MAX);\n",
    "    color *= rblExposure;\n",
    "#if RBL_TONEMAP == 1\n",
    "    color = color/(1.0 + color);\n",
    "#elif RBL_TONEMAP == 2\n",
    "    color = min(color, vec3(RBL_HALF_MAX));\n",
    "    color = clamp(color*(2.51*color + 0.03)/(color*(2.43*color + 0.59) + 0.14), 0.0, 1.0);\n",
    "#endif\n",
    "#if defined(RBL_LINEAR_OUTPUT)\n",
    "    return min(color, vec3(RBL_HALF_MAX));\n",
    "#elif defined(RBL_GAMMA)\n",
    "    return pow(clamp(color, 0.0, 1.0), vec3(1.0/RBL_GAMMA));\n",
    "#else\n",
    "    return rblLinearToSrgb(color);\n",
    "#endif\n",
    "}\n",
    NULL };
static const char *const rbl__shader_relief[] = {
    "// Relief self-shadow: embossed detail shadows the sprite itself. The material texture's height\n",
    "// channel (0..1, scaled by rblRelief.x texels) is marched from the shaded texel toward each light in\n",
    "// the card's tangent space, at RBL_RELIEF_STEPS evenly spaced samples of the ray up to where it\n",
    "// clears the highest height; a sample whose texel stands above the ray shadows the light. Heights are\n",
    "// read texel by texel (unfiltered, base level; the mirror of tests' double-precision march). The ray's\n",
    "// horizontal reach is capped at 8 climbs (light below 7 degrees), and a texel is taken as square:\n",
    "// a sprite drawn stretched sees its shadows stretched with it.\n",
    "// Included by material.glsl; compiled only with:\n",
    "//   RBL_RELIEF_STEPS n      samples per light (RblLitShaderDesc.reliefSteps)\n",
    "//   RBL_HEIGHT_CHANNEL c    material texture component holding height (3 b, 4 a)\n",
    "#include \"surface.glsl\"\n",
    "\n",
    "#ifdef RBL_RELIEF_STEPS\n",
    "uniform vec4 rblRelief;     // x height 1 in texels (0 = flat: nothing marched), zw 1/size of the material texture\n",
    "vec2 rblReliefAt;           // the shaded point in texels of the material texture (set by rblMaterialSurface)\n",
    "float rblReliefBase;        // its height in texels\n",
    "vec3 rblReliefU, rblReliefV, rblReliefN;   // world directions of +U, +V (down the image) and out of the card's shaded side\n",
    "\n",
    "float rblReliefHeight(sampler2D map, vec2 texel)\n",
    "{\n",
    "    vec2 at = clamp(floor(texel), vec2(0.0), floor(1.0/rblRelief.zw + 0.5) - 1.0);\n",
    "#if RBL_GLSL >= 300\n",
    "    vec4 m = texelFetch(map, ivec2(at), 0);\n",
    "#else\n",
    "    vec4 m = texture2D(map, (at + 0.5)*rblRelief.zw);\n",
    "#endif\n",
    "    return m[RBL_HEIGHT_CHANNEL - 1]*rblRelief.x;\n",
    "}\n",
    "\n",
    "// The shaded point: uv, its tangent frame (unit world +U, +V, shaded-side normal)\n",
    "void rblReliefSetup(sampler2D map, vec2 uv, vec3 u, vec3 v, vec3 n)\n",
    "{\n",
    "    rblReliefAt = uv/rblRelief.zw;\n",
    "    rblReliefU = u; rblReliefV = v; rblReliefN = n;\n",
    "    rblReliefBase = rblReliefHeight(map, rblReliefAt);\n",
    "}\n",
    "\n",
    "// Light let through toward unit direction l: 0 behind relief, else 1\n",
    "float rblReliefMarch(sampler2D map, vec3 l)\n",
    "{\n",
    "    vec3 d = vec3(dot(l, rblReliefU), dot(l, rblReliefV), dot(l, rblReliefN));\n",
    "    float rise = rblRelief.x - rblReliefBase;          // texels to the top\n",
    "    if (!(d.z > 0.0) || !(rise > 0.0)) return 1.0;    // behind the card (the lights decide), or nothing above\n",
    "    vec2 reach = d.xy*(rise/max(d.z, 0.125));\n",
    "    float delta = 1.0/float(RBL_RELIEF_STEPS);\n",
    "    for (int i = 1; i <= RBL_RELIEF_STEPS; i++)\n",
    "    {\n",
    "        float f = float(i)*delta;\n",
    "        if (rblReliefHeight(map, rblReliefAt + reach*f) > rblReliefBase + rise*f) return 0.0;\n",
    "    }\n",
    "    return 1.0;\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_scene_composite_fs[] = {
    "// The opaque world drawn between RblBeginSceneDepth and RblEndSceneDepth, shown on the caller's target\n",
    "// with its depth, so later draws are depth tested against it (soft particles also read that depth as a\n",
    "// texture). Where nothing was drawn the caller's target shows through. GLSL ES 1.00 writes depth only\n",
    "// with EXT_frag_depth (the loader enables it where it exists).\n",
    "#include \"dialect.glsl\"\n",
    "\n",
    "uniform sampler2D texture0;             // the scene target's colour\n",
    "uniform sampler2D rblSceneDepthMap;     // its depth\n",
    "RBL_VARYING vec2 fragUv;\n",
    "#if RBL_GLSL >= 300\n",
    "out vec4 finalColor;\n",
    "#else\n",
    "#define finalColor gl_FragColor\n",
    "#endif\n",
    "\n",
    "void main()\n",
    "{\n",
    "    float depth = texture(rblSceneDepthMap, fragUv).r;\n",
    "    if (depth >= 1.0) discard;\n",
    "    finalColor = vec4(texture(texture0, fragUv).rgb, 1.0);\n",
    "#if RBL_GLSL >= 120\n",
    "    gl_FragDepth = depth;\n",
    "#elif defined(GL_EXT_frag_depth)\n",
    "    gl_FragDepthEXT = depth;\n",
    "#endif\n",
    "}\n",
    NULL };
static const char *const rbl__shader_scene_composite_vs[] = {
    "// Full-screen triangle from a vertex buffer (GLSL 1 has no gl_VertexID): RblEndSceneDepth shows the\n",
    "// scene target on the caller's target. Pairs with scene_composite.fs.glsl.\n",
    "#include \"dialect.glsl\"\n",
    "\n",
    "RBL_ATTRIBUTE vec3 vertexPosition;      // (-1,-1) (3,-1) (-1,3)\n",
    "RBL_VARYING vec2 fragUv;                // scene target coordinate of this pixel (0..1)\n",
    "\n",
    "void main()\n",
    "{\n",
    "    fragUv = vertexPosition.xy*0.5 + 0.5;\n",
    "    gl_Position = vec4(vertexPosition.xy, 0.0, 1.0);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_shadow_caster_fs[] = {
    "// Shadow pass, fragment stage. The alpha test is the colour pass's own (albedo x colDiffuse x vertex\n",
    "// colour against the material's cutoff): a sprite's silhouette casts the shadow, not its quad.\n",
    "// Nothing else is sampled. The depth target gets the nearest caster; the casters target (RGBA8,\n",
    "// RblShadowMap.casters; absent with RblShadowDesc.selfShadow) gets what shadows.glsl reads of it:\n",
    "//   rg   its distance along the light's axis as a 16-bit code (high byte first): orthographic, the\n",
    "//        window depth (linear over near..far); perspective, log(d/near)/log(far/near), a step a fixed\n",
    "//        share of the distance, as a perspective texel is\n",
    "//   ba   its caster identity: a billboard's from its pivot, 0 for Models (shadows.glsl)\n",
    "// Blended casters (RBL_CASTER_TRANSMIT, RblBeginShadowBlend) write the transmittance target instead\n",
    "// (shadow_tint.glsl): rgb what they let through, multiplied in by the blending (1 - alpha, or\n",
    "// mix(1, colour, alpha) with rblCasterTint 1), a the distance code's top 8 bits (kept by min blending)\n",
    "#include \"material.glsl\"\n",
    "\n",
    "uniform vec4 rblCasterDepth;    // perspective (0/1), near, far, log(far/near)\n",
    "#ifdef RBL_CASTER_TRANSMIT\n",
    "uniform float rblCasterTint;    // 1: tinted by the caster's colour, 0: grey (coverage only)\n",
    "#endif\n",
    "#if RBL_GLSL >= 300\n",
    "out vec4 rblOutCaster;\n",
    "#else\n",
    "#define rblOutCaster gl_FragColor\n",
    "#endif\n",
    "\n",
    "void main()\n",
    "{\n",
    "    float alpha;\n",
    "    vec3 emission, tangentNormal;\n",
    "    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);     // discards below the cutoff\n",
    "    float code = gl_FragCoord.z;\n",
    "    if (rblCasterDepth.x > 0.5) code = log(max(1.0/gl_FragCoord.w, rblCasterDepth.y)/rblCasterDepth.y)/rblCasterDepth.w;\n",
    "#ifdef RBL_CASTER_TRANSMIT\n",
    "    vec3 through = (rblCasterTint > 0.5)? sp.albedo : vec3(0.0);\n",
    "    rblOutCaster = vec4(mix(vec3(1.0), through, clamp(alpha, 0.0, 1.0)), floor(clamp(code, 0.0, 1.0)*255.0)/255.0);\n",
    "    return;\n",
    "#endif\n",
    "    float v = floor(clamp(code, 0.0, 1.0)*65535.0 + 0.5);\n",
    "    float high = floor(v/256.0);\n",
    "    rblOutCaster = vec4(high/255.0, (v - high*256.0)/255.0, sp.caster);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_shadow_tint[] = {
    "// Shadow tint: what blended casters (smoke, coloured glass; RblBeginShadowBlend) let through to a\n",
    "// receiver behind them. Each map with RblShadowDesc.transmittance has an RGBA8 target: rgb the product\n",
    "// of the blended casters' transmittance over that texel (coverage a: 1 - a, or mix(1, colour, a)\n",
    "// coloured), a the nearest one's distance code in 8 bits (shadow_caster.fs.glsl); only casters in\n",
    "// front of the opaque depth were kept. A receiver more than 1.5 code steps behind that distance\n",
    "// takes the texel's tint: a caster never tints itself or what lies in front of it. Bilinear over the\n",
    "// 2 x 2 texels around the point (the tint's edge is as soft as PCF 1's). Forward receivers and the\n",
    "// G-buffer's light passes (RblGBufferDesc.shadowTransmittance).\n",
    "//   RBL_SHADOW_TINT          RblLitShaderDesc.shadowTransmittance (needs RBL_SHADOWS > 0)\n",
    "#include \"shadows.glsl\"\n",
    "\n",
    "#if defined(RBL_SHADOW_TINT) && (RBL_SHADOWS > 0)\n",
    "uniform sampler2D rblShadowTint0;           // units RBL_SHADOW_TINT_TEXTURE_UNIT + k (white 1 x 1 where a map has none)\n",
    "#if RBL_SHADOWS > 1\n",
    "uniform sampler2D rblShadowTint1;\n",
    "#endif\n",
    "#if RBL_SHADOWS > 2\n",
    "uniform sampler2D rblShadowTint2;\n",
    "#endif\n",
    "#if RBL_SHADOWS > 3\n",
    "uniform sampler2D rblShadowTint3;\n",
    "#endif\n",
    "\n",
    "vec3 rblTintLookup(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, float size, vec3 position)\n",
    "{\n",
    "    vec4 c = rblShadowTransform(r0, r1, r2, r3, position);\n",
    "    if (!(c.w > 0.0)) return vec3(1.0);\n",
    "    vec3 q = c.xyz/c.w;\n",
    "    if (!((q.x >= 0.0) && (q.x <= 1.0) && (q.y >= 0.0) && (q.y <= 1.0) && (q.z < 1.0))) return vec3(1.0);\n",
    "    bool perspective = mod(prm.y, 2.0) > 0.5;\n",
    "    float d = rblShadowDistance(max(q.z, 0.0), vec4(prm.x, perspective? 1.0 : 0.0, prm.zw));\n",
    "    float code = perspective? log(max(d, prm.z)/prm.z)/log(prm.w/prm.z) : (d - prm.z)/(prm.w - prm.z);\n",
    "    vec2 st = q.xy*size - 0.5;\n",
    "    vec2 base = floor(st), f = st - base;\n",
    "    vec3 sum = vec3(0.0);\n",
    "    for (int j = 0; j < 2; j++)\n",
    "        for (int i = 0; i < 2; i++)\n",
    "        {\n",
    "            vec2 at = clamp(base + vec2(float(i), float(j)), vec2(0.0), vec2(size - 1.0));\n",
    "            vec4 t = rblFetch(map, ivec2(at), size);\n",
    "            float w = ((i == 0)? 1.0 - f.x : f.x)*((j == 0)? 1.0 - f.y : f.y);\n",
    "            sum += w*((code > t.a + 1.5/255.0)? t.rgb : vec3(1.0));\n",
    "        }\n",
    "    return sum;\n",
    "}\n",
    "\n",
    "// Map k's tint at a world position (1: untinted)\n",
    "vec3 rblShadowTint(int k, vec3 position)\n",
    "{\n",
    "    if (k == 0) return rblTintLookup(rblShadowTint0, rblShadowMatrix[0], rblShadowMatrix[1], rblShadowMatrix[2], rblShadowMatrix[3], rblShadowParams[0], rblShadowBias[0].w, position);\n",
    "#if RBL_SHADOWS > 1\n",
    "    if (k == 1) return rblTintLookup(rblShadowTint1, rblShadowMatrix[4], rblShadowMatrix[5], rblShadowMatrix[6], rblShadowMatrix[7], rblShadowParams[1], rblShadowBias[1].w, position);\n",
    "#endif\n",
    "#if RBL_SHADOWS > 2\n",
    "    if (k == 2) return rblTintLookup(rblShadowTint2, rblShadowMatrix[8], rblShadowMatrix[9], rblShadowMatrix[10], rblShadowMatrix[11], rblShadowParams[2], rblShadowBias[2].w, position);\n",
    "#endif\n",
    "#if RBL_SHADOWS > 3\n",
    "    if (k == 3) return rblTintLookup(rblShadowTint3, rblShadowMatrix[12], rblShadowMatrix[13], rblShadowMatrix[14], rblShadowMatrix[15], rblShadowParams[3], rblShadowBias[3].w, position);\n",
    "#endif\n",
    "    return vec3(1.0);\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_shadows[] = {
    "// Shadows: the shadow maps a receiver samples and the lookup (bias, receiver plane, PCF). Which\n",
    "// light a map shadows is the lights' business (lights.glsl, deferred_volume.fs.glsl).\n",
    "//   RBL_SHADOWS n             shadow maps sampled (0..4; rblShadowMap0..3), each shadowing one light\n",
    "//   RBL_SHADOW_FILTER k       PCF footprint in texels per side: (k + 1)^2 depth fetches per lookup\n",
    "//   RBL_SHADOW_KIND<k>        map k's kind: 0 one light camera (directional, spot), 1 omni (a point\n",
    "//                             light: six cube faces, tiles 3 x 2 of one target, +X -X +Y / -Y +Z -Z),\n",
    "//                             2 cascades (2..4 tiles in a row); every tile is looked up alike\n",
    "//   RBL_SHADOW_FORMAT<k>      map k's format: perspective + 2 for the casters target (else a depth texture)\n",
    "//   RBL_SHADOW_OMNI           some map is omni (its face code is compiled in)\n",
    "//   RBL_SHADOW_CASCADES       some map is cascaded (its cascade code is compiled in)\n",
    "// Kind and format are compiled per map (the program registry compiles the variant a scene's maps\n",
    "// need, RblSetScene): a program receiving one-camera maps holds no tile, face or cascade code, and\n",
    "// no lookup branches on a format at run time.\n",
    "#include \"surface.glsl\"\n",
    "\n",
    "#if RBL_SHADOWS > 0\n",
    "uniform vec4 rblShadowMatrix[4*RBL_SHADOWS]; // rows 4k..4k+3: world -> (u, v, window depth, w) of map k (rows: no\n",
    "                                            // transpose convention to differ between GL and ES uploads)\n",
    "                                            // cascades: light-frame rows (right, up, window depth), the camera plane\n",
    "uniform vec4 rblShadowParams[RBL_SHADOWS];  // texel world size (perspective: per unit distance), format, near, far; format:\n",
    "                                            // 0, 1 depth texture (orthographic, perspective); 2, 3 the casters\n",
    "                                            // target (RGBA8: 16-bit distance code, caster identity); + 4 x kind\n",
    "                                            // (0 one camera, 1 omni, 2..4 cascades)\n",
    "uniform vec4 rblShadowBias[RBL_SHADOWS];    // constant, slope, normal offset (all in texels), tile size in texels\n",
    "uniform vec4 rblShadowAxes[2*RBL_SHADOWS];  // right and up of map k's light camera (its axis = cross(up, right));\n",
    "                                            // cascades: w the first split, the blend band's share\n",
    "#if defined(RBL_SHADOW_OMNI) || defined(RBL_SHADOW_CASCADES)\n",
    "uniform vec4 rblShadowTiles[4*RBL_SHADOWS]; // omni: [4k] light position, tan of a face's half width; cascade c:\n",
    "                                            // [4k + c] 1/width, -left/width, -bottom/width, far split\n",
    "#endif\n",
    "uniform sampler2D rblShadowMap0;            // casters targets or depth textures (texture units RBL_SHADOW_TEXTURE_UNIT + k)\n",
    "#if RBL_SHADOWS > 1\n",
    "uniform sampler2D rblShadowMap1;\n",
    "#endif\n",
    "#if RBL_SHADOWS > 2\n",
    "uniform sampler2D rblShadowMap2;\n",
    "#endif\n",
    "#if RBL_SHADOWS > 3\n",
    "uniform sampler2D rblShadowMap3;\n",
    "#endif\n",
    "#endif\n",
    "\n",
    "#if RBL_SHADOWS > 0\n",
    "// Distance along the light's axis from a value v of map k (prm: texel, format, near, far): a window\n",
    "// depth, or a casters target's code (shadow_caster.fs.glsl); both are linear when orthographic\n",
    "float rblShadowDistance(float v, vec4 prm)\n",
    "{\n",
    "    if (prm.y > 2.5) return prm.z*exp(v*log(prm.w/prm.z));\n",
    "    if ((prm.y > 0.5) && (prm.y < 1.5)) return prm.z*prm.w/(prm.w - v*(prm.w - prm.z));\n",
    "    return prm.z + v*(prm.w - prm.z);\n",
    "}\n",
    "\n",
    "// Fraction of light k's map lets through to a surface point of unit normal n (either sign) lit at\n",
    "// cos(incidence) NdotL (> 0), that lies on the billboard of identity caster (0: a Model). Depths are\n",
    "// compared as distances along the light's axis, in world units:\n",
    "//   normal offset   the lookup moves along n*side (side: +-1 toward the light) by normal*texel*\n",
    "//                   sin(incidence) (lateral shift <= that)\n",
    "//   receiver plane  each PCF fetch is compared with the receiver's own plane extended to that texel's\n",
    "//                   centre (depth gradient from n in the light's frame, clamped at 10 texels per\n",
    "//                   texel), so a flat receiver never shadows itself at any incidence below 84 degrees\n",
    "//   depth bias      texel*(constant + slope*tan(incidence)), tan clamped at 10; a casters target\n",
    "//                   adds half its code's step (its rounding)\n",
    "//   identity        a fetch holding the point's own caster (same identity, not 0) lets light through:\n",
    "//                   a billboard is flat, so its own card never shadows it, wherever the pass turned it\n",
    "//                   (the light-facing card, the AXIS tilt) and however its normal map bends the normal\n",
    "// PCF: a box of RBL_SHADOW_FILTER texels per side over bilinear-weighted comparisons, (k + 1)^2\n",
    "// fetches: at k = 1 the footprint of hardware 2x2 comparison filtering (rlgl exposes no compare mode).\n",
    "// Outside the map, behind a spot light or beyond the far plane the point is lit, and so is a fetch\n",
    "// outside the map or of a texel nothing was drawn into.\n",
    "// Map k's uniforms come in as arguments, indexed by constants at the call: GLSL ES 1.00 fragment\n",
    "// stages may index uniform arrays only by constants and loop indices. prm.y (the format) is map k's\n",
    "// compiled RBL_SHADOW_FORMAT<k> at every call, so the compiler folds each branch on it away.\n",
    "vec4 rblShadowTransform(vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec3 p)\n",
    "{\n",
    "    vec4 h = vec4(p, 1.0);\n",
    "    return vec4(dot(r0, h), dot(r1, h), dot(r2, h), dot(r3, h));\n",
    "}\n",
    "\n",
    "// tile: the map's texel origin in its target, the target's size in texels\n",
    "float rblShadowLookup(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, vec4 bias, vec3 right, vec3 up, vec4 tile,\n",
    "                      vec3 position, vec3 n, float NdotL, float side, vec2 caster)\n",
    "{\n",
    "    bool coded = prm.y > 1.5;                  // the casters target (else a depth texture)\n",
    "    bool skipOwn = coded && (caster.x + caster.y > 0.0);\n",
    "    vec3 along = cross(up, right);\n",
    "    vec4 c0 = rblShadowTransform(r0, r1, r2, r3, position);\n",
    "    bool perspective = mod(prm.y, 2.0) > 0.5;\n",
    "    float texel = prm.x*(perspective? max(c0.w, 0.0) : 1.0);       // world size of a texel here\n",
    "    float sinI = sqrt(max(1.0 - NdotL*NdotL, 0.0));\n",
    "    float tanI = min(sinI/max(NdotL, 1e-4), 10.0);\n",
    "    vec4 c = rblShadowTransform(r0, r1, r2, r3, position + n*(bias.z*texel*sinI*side));\n",
    "    if (!(c.w > 0.0)) return 1.0;\n",
    "    vec3 q = c.xyz/c.w;\n",
    "    if (!((q.x >= 0.0) && (q.x <= 1.0) && (q.y >= 0.0) && (q.y <= 1.0) && (q.z < 1.0))) return 1.0;\n",
    "    // The receiver's own distance from its window depth (a depth texture's format, whatever the map holds)\n",
    "    float z = rblShadowDistance(max(q.z, 0.0), vec4(prm.x, perspective? 1.0 : 0.0, prm.zw)) - texel*(bias.x + bias.y*tanI);\n",
    "    if (coded) z -= ((prm.y > 2.5)? z*log(prm.w/prm.z) : prm.w - prm.z)*(0.5/65535.0);\n",
    "    // Receiver plane: distance change per texel step along the map's x and y. A perspective map's\n",
    "    // texel is a ray (along + right x + up y, x and y its tangents at the texel centre): the plane's\n",
    "    // distance changes with the ray's angle to it, not the axis's (a floor seen by a cube side face\n",
    "    // lies along the axis), and is the same for n and -n\n",
    "    vec3 ray = along, nf = n;\n",
    "    if (perspective)\n",
    "    {\n",
    "        ray += (right*(2.0*q.x - 1.0) + up*(2.0*q.y - 1.0))*(0.5*prm.x*bias.w);\n",
    "        nf = (dot(n, ray) > 0.0)? -n : n;\n",
    "    }\n",
    "    vec2 slope = vec2(dot(nf, right), dot(nf, up))/max(-dot(nf, ray), 1e-4);\n",
    "    slope *= min(1.0, 10.0/max(length(slope), 1e-20))*texel;\n",
    "    float size = bias.w;\n",
    "    vec2 st = q.xy*size - 0.5*float(RBL_SHADOW_FILTER);         // first bilinear tap's position - 0.5, in texels\n",
    "    vec2 base = floor(st), f = st - base;\n",
    "    ivec2 b0 = ivec2(base), top = ivec2(int(size) - 1);\n",
    "    vec2 origin = base + 0.5 - q.xy*size;                       // first fetched centre relative to the point\n",
    "    float lit = 0.0;\n",
    "    for (int j = 0; j <= RBL_SHADOW_FILTER; j++)\n",
    "    {\n",
    "        float wy = (j == 0)? 1.0 - f.y : ((j == RBL_SHADOW_FILTER)? f.y : 1.0);\n",
    "        for (int i = 0; i <= RBL_SHADOW_FILTER; i++)\n",
    "        {\n",
    "            float wx = (i == 0)? 1.0 - f.x : ((i == RBL_SHADOW_FILTER)? f.x : 1.0);\n",
    "            // Texels outside the map or never written (cleared to 1: beyond the far plane) hold no occluder\n",
    "            ivec2 at = b0 + ivec2(i, j);\n",
    "            vec4 t = (all(greaterThanEqual(at, ivec2(0))) && all(lessThanEqual(at, top)))? rblFetch(map, at + ivec2(tile.xy), tile.zw) : vec4(1.0);\n",
    "            float raw = t.r;\n",
    "            bool through = raw >= 1.0;       // nothing drawn there (cleared to 1), or the point's own caster\n",
    "            if (coded)\n",
    "            {\n",
    "                float code = floor(t.r*255.0 + 0.5)*256.0 + floor(t.g*255.0 + 0.5);\n",
    "                raw = code/65535.0;\n",
    "                through = (code > 65534.5) || (skipOwn && all(lessThan(abs(t.ba - caster), vec2(0.5/255.0))));\n",
    "            }\n",
    "            float receiver = z + dot(slope, origin + vec2(float(i), float(j)));\n",
    "            lit += (through || (receiver <= rblShadowDistance(raw, prm)))? wx*wy : 0.0;\n",
    "        }\n",
    "    }\n",
    "    return lit/float(RBL_SHADOW_FILTER*RBL_SHADOW_FILTER);\n",
    "}\n",
    "\n",
    "#if defined(RBL_SHADOW_OMNI)\n",
    "// An omni map: the cube face of the point's major axis from the light (rows built as the CPU's face\n",
    "// camera, the guard band keeping the PCF footprint inside the face), looked up as one camera\n",
    "float rblShadowOmni(sampler2D map, vec4 prm, vec4 bias, vec4 t0, vec3 position, vec3 n, float NdotL, float side, vec2 caster)\n",
    "{\n",
    "    float size = bias.w;\n",
    "    vec3 d = position - t0.xyz, a = abs(d);\n",
    "    float face = (a.x >= a.y && a.x >= a.z)? ((d.x < 0.0)? 1.0 : 0.0) : ((a.y >= a.z)? ((d.y < 0.0)? 3.0 : 2.0) : ((d.z < 0.0)? 5.0 : 4.0));\n",
    "    vec3 along = (face < 1.5)? vec3(1.0, 0.0, 0.0) : ((face < 3.5)? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));\n",
    "    along *= (mod(face, 2.0) > 0.5)? -1.0 : 1.0;\n",
    "    vec3 up = (abs(along.y) > 0.5)? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);\n",
    "    vec3 right = cross(along, up);\n",
    "    float e = dot(along, t0.xyz), s = 0.5/t0.w, g = prm.w/(prm.w - prm.z);\n",
    "    vec4 r3 = vec4(along, -e);\n",
    "    vec4 r0 = vec4(right*s, -dot(right, t0.xyz)*s) + 0.5*r3;\n",
    "    vec4 r1 = vec4(up*s, -dot(up, t0.xyz)*s) + 0.5*r3;\n",
    "    vec4 r2 = g*r3 - vec4(0.0, 0.0, 0.0, g*prm.z);\n",
    "    vec4 tile = vec4(mod(face, 3.0)*size, floor(face/3.0)*size, 3.0*size, 2.0*size);\n",
    "    return rblShadowLookup(map, r0, r1, r2, r3, prm, bias, right, up, tile, position, n, NdotL, side, caster);\n",
    "}\n",
    "#endif\n",
    "\n",
    "#if defined(RBL_SHADOW_CASCADES)\n",
    "// A cascaded map (kind: the cascade count, from the uniforms): the first cascade whose far split lies\n",
    "// beyond the point's view depth; inside the last blend share of its range the next cascade's lookup\n",
    "// is mixed in linearly (each cascade's map covers the previous one's band). One lookup call in the\n",
    "// program; a second pass in a blend band\n",
    "float rblShadowCascades(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, float kind, vec4 bias, vec4 ax0, vec4 ax1,\n",
    "                        vec4 t0, vec4 t1, vec4 t2, vec4 t3, vec3 position, vec3 n, float NdotL, float side, vec2 caster)\n",
    "{\n",
    "    float size = bias.w;\n",
    "    float depth = dot(r3, vec4(position, 1.0));\n",
    "    float c = (depth < t0.w)? 0.0 : ((depth < t1.w)? 1.0 : ((depth < t2.w)? 2.0 : 3.0));\n",
    "    float end = (c < 0.5)? t0.w : ((c < 1.5)? t1.w : ((c < 2.5)? t2.w : t3.w));\n",
    "    if (!(c < kind) || !(depth < end)) return 1.0;\n",
    "    float band = ax1.w*(end - ((c < 0.5)? ax0.w : ((c < 1.5)? t0.w : ((c < 2.5)? t1.w : t2.w))));\n",
    "    float mixing = ((c + 1.0 < kind) && (band > 0.0))? clamp((depth - (end - band))/band, 0.0, 1.0) : 0.0;\n",
    "    vec4 p = prm;\n",
    "    float first = 1.0, lit = 1.0;\n",
    "    for (int i = 0; i < 2; i++)\n",
    "    {\n",
    "        if ((i == 1) && !(mixing > 0.0)) break;\n",
    "        float ci = c + float(i);\n",
    "        vec4 t = (ci < 0.5)? t0 : ((ci < 1.5)? t1 : ((ci < 2.5)? t2 : t3));\n",
    "        p.x = 1.0/(t.x*size);\n",
    "        lit = rblShadowLookup(map, vec4(r0.xyz*t.x, t.y), vec4(r1.xyz*t.x, t.z), r2, vec4(0.0, 0.0, 0.0, 1.0), p, bias, ax0.xyz, ax1.xyz,\n",
    "                              vec4(ci*size, 0.0, kind*size, size), position, n, NdotL, side, caster);\n",
    "        if (i == 0) first = lit;\n",
    "    }\n",
    "    return (mixing > 0.0)? mix(first, lit, mixing) : first;\n",
    "}\n",
    "#endif\n",
    "\n",
    "// Map k's lookup by its compiled kind and format (RBL_SHADOW_KIND<k>, RBL_SHADOW_FORMAT<k>): k a literal\n",
    "#define RBL_SHADOW_ONE_OF(map, k, format) rblShadowLookup(map, rblShadowMatrix[4*k], rblShadowMatrix[4*k + 1], rblShadowMatrix[4*k + 2], rblShadowMatrix[4*k + 3], vec4(rblShadowParams[k].x, format, rblShadowParams[k].zw), rblShadowBias[k], rblShadowAxes[2*k].xyz, rblShadowAxes[2*k + 1].xyz, vec4(0.0, 0.0, rblShadowBias[k].ww), position, n, NdotL, side, caster)\n",
    "#define RBL_SHADOW_OMNI_OF(map, k, format) rblShadowOmni(map, vec4(rblShadowParams[k].x, format, rblShadowParams[k].zw), rblShadowBias[k], rblShadowTiles[4*k], position, n, NdotL, side, caster)\n",
    "#define RBL_SHADOW_CASCADES_OF(map, k, format) rblShadowCascades(map, rblShadowMatrix[4*k], rblShadowMatrix[4*k + 1], rblShadowMatrix[4*k + 2], rblShadowMatrix[4*k + 3], vec4(rblShadowParams[k].x, format, rblShadowParams[k].zw), floor(rblShadowParams[k].y/4.0 + 0.01), rblShadowBias[k], rblShadowAxes[2*k], rblShadowAxes[2*k + 1], rblShadowTiles[4*k], rblShadowTiles[4*k + 1], rblShadowTiles[4*k + 2], rblShadowTiles[4*k + 3], position, n, NdotL, side, caster)\n",
    "\n",
    "float rblShadow(int k, vec3 position, vec3 n, float NdotL, float side, vec2 caster)\n",
    "{\n",
    "#if RBL_SHADOW_KIND0 == 1\n",
    "    if (k == 0) return RBL_SHADOW_OMNI_OF(rblShadowMap0, 0, float(RBL_SHADOW_FORMAT0));\n",
    "#elif RBL_SHADOW_KIND0 == 2\n",
    "    if (k == 0) return RBL_SHADOW_CASCADES_OF(rblShadowMap0, 0, float(RBL_SHADOW_FORMAT0));\n",
    "#else\n",
    "    if (k == 0) return RBL_SHADOW_ONE_OF(rblShadowMap0, 0, float(RBL_SHADOW_FORMAT0));\n",
    "#endif\n",
    "#if RBL_SHADOWS > 1\n",
    "#if RBL_SHADOW_KIND1 == 1\n",
    "    if (k == 1) return RBL_SHADOW_OMNI_OF(rblShadowMap1, 1, float(RBL_SHADOW_FORMAT1));\n",
    "#elif RBL_SHADOW_KIND1 == 2\n",
    "    if (k == 1) return RBL_SHADOW_CASCADES_OF(rblShadowMap1, 1, float(RBL_SHADOW_FORMAT1));\n",
    "#else\n",
    "    if (k == 1) return RBL_SHADOW_ONE_OF(rblShadowMap1, 1, float(RBL_SHADOW_FORMAT1));\n",
    "#endif\n",
    "#endif\n",
    "#if RBL_SHADOWS > 2\n",
    "#if RBL_SHADOW_KIND2 == 1\n",
    "    if (k == 2) return RBL_SHADOW_OMNI_OF(rblShadowMap2, 2, float(RBL_SHADOW_FORMAT2));\n",
    "#elif RBL_SHADOW_KIND2 == 2\n",
    "    if (k == 2) return RBL_SHADOW_CASCADES_OF(rblShadowMap2, 2, float(RBL_SHADOW_FORMAT2));\n",
    "#else\n",
    "    if (k == 2) return RBL_SHADOW_ONE_OF(rblShadowMap2, 2, float(RBL_SHADOW_FORMAT2));\n",
    "#endif\n",
    "#endif\n",
    "#if RBL_SHADOWS > 3\n",
    "#if RBL_SHADOW_KIND3 == 1\n",
    "    if (k == 3) return RBL_SHADOW_OMNI_OF(rblShadowMap3, 3, float(RBL_SHADOW_FORMAT3));\n",
    "#elif RBL_SHADOW_KIND3 == 2\n",
    "    if (k == 3) return RBL_SHADOW_CASCADES_OF(rblShadowMap3, 3, float(RBL_SHADOW_FORMAT3));\n",
    "#else\n",
    "    if (k == 3) return RBL_SHADOW_ONE_OF(rblShadowMap3, 3, float(RBL_SHADOW_FORMAT3));\n",
    "#endif\n",
    "#endif\n",
    "    return 1.0;\n",
    "}\n",
    "\n",
    "// Light k's map at shading point s for the light toward l: biased by the rasterised surface (its\n",
    "// face; a card is two-sided: the side toward the light), whatever normal shades it. The normal\n",
    "// offset fades out through edge-on (|cos| < 1/20), so it never jumps from one side to the other\n",
    "float rblShadowAt(int k, RblShadingPoint s, vec3 l)\n",
    "{\n",
    "    float c = dot(s.face, l);\n",
    "    return rblShadow(k, s.position, s.face, max(abs(c), 1e-4), clamp(c*20.0, -1.0, 1.0), s.caster);\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_skinning[] = {
    "// GPU skinning of raylib Models (RBL_SKINNING: RblLitShaderDesc.skinning, and the skinned caster):\n",
    "// raylib's bone attributes (DrawMesh binds them by these names when raylib is built with\n",
    "// SUPPORT_GPU_SKINNING) and the Model's boneMatrices (RblDrawModel uploads them). Same sum as raylib's\n",
    "// CPU skinning: p' = sum w_k M_k p, n' = sum w_k M_k^-T n (normals with the inverse transpose, so a\n",
    "// non-uniformly scaled bone keeps them perpendicular); tangents lie in the surface: sum w_k M_k t.\n",
    "// Weights are used as given (not renormalised, as raylib's CPU path); a vertex whose weights are all\n",
    "// zero belongs to no bone and keeps its bind pose (raylib's sum would put it at the origin).\n",
    "#include \"common.glsl\"\n",
    "\n",
    "#ifdef RBL_SKINNING\n",
    "RBL_ATTRIBUTE vec4 vertexBoneIndices;      // unsigned bytes, not normalised: 0..255 as floats\n",
    "RBL_ATTRIBUTE vec4 vertexBoneWeights;\n",
    "uniform mat4 boneMatrices[RBL_MAX_BONES];\n",
    "\n",
    "void rblSkin(inout vec3 position, inout vec3 normal, inout vec3 tangent)\n",
    "{\n",
    "    vec3 p = vec3(0.0), n = vec3(0.0), t = vec3(0.0);\n",
    "    float total = 0.0;\n",
    "    for (int k = 0; k < 4; k++)\n",
    "    {\n",
    "        float w = vertexBoneWeights[k];\n",
    "        // A zero weight adds nothing, even from a bone matrix never uploaded\n",
    "        if (w == 0.0) continue;\n",
    "        total += abs(w);\n",
    "        mat4 m = boneMatrices[int(clamp(vertexBoneIndices[k] + 0.5, 0.0, float(RBL_MAX_BONES) - 0.5))];\n",
    "        vec3 a = m[0].xyz, b = m[1].xyz, c = m[2].xyz;\n",
    "        p += w*(a*position.x + b*position.y + c*position.z + m[3].xyz);\n",
    "        // Inverse transpose = cofactors/det: columns b x c, c x a, a x b (no inverse(), which GLSL ES 1.00\n",
    "        // lacks); a singular bone keeps its cofactor direction rather than dividing by zero\n",
    "        vec3 ca = cross(b, c), cb = cross(c, a), cc = cross(a, b);\n",
    "        float det = dot(a, ca);\n",
    "        n += w*(ca*normal.x + cb*normal.y + cc*normal.z)/((abs(det) > 1e-30)? det : 1.0);\n",
    "        t += w*(a*tangent.x + b*tangent.y + c*tangent.z);\n",
    "    }\n",
    "    if (total > 0.0) { position = p; normal = n; tangent = t; }\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_soft[] = {
    "// Soft particles: a blended billboard fades where it meets the opaque scene behind it, by the depth\n",
    "// distance between the two (RblScene.depth: a RblLoadSceneTarget's or a G-buffer's depth texture,\n",
    "// the same size as the target drawn into). No depth texture in the scene: no fade.\n",
    "//   RBL_SOFT_PARTICLES         compiled in (RblLitShaderDesc.softParticles)\n",
    "#include \"common.glsl\"\n",
    "\n",
    "#ifdef RBL_SOFT_PARTICLES\n",
    "uniform sampler2D rblSceneDepth;    // texture unit RBL_SCENE_DEPTH_TEXTURE_UNIT\n",
    "uniform vec4 rblSoftDepth;          // projection m10, m14, orthographic (0/1; -1 = no scene depth), fade distance (world units)\n",
    "uniform vec2 rblSoftDepthTexel;     // 1/width, 1/height of the scene depth\n",
    "\n",
    "// Distance in front of the camera of a window depth d (0..1), from the projection's depth row\n",
    "float rblViewDepth(float d)\n",
    "{\n",
    "    float ndc = d*2.0 - 1.0;\n",
    "    return (rblSoftDepth.z > 0.5)? (rblSoftDepth.y - ndc)/rblSoftDepth.x : rblSoftDepth.y/(ndc + rblSoftDepth.x);\n",
    "}\n",
    "\n",
    "// 0 where the fragment lies on or behind the scene's surface, 1 a fade distance or more in front\n",
    "float rblSoftFade()\n",
    "{\n",
    "    if (rblSoftDepth.z < -0.5) return 1.0;\n",
    "    float scene = rblViewDepth(texture(rblSceneDepth, gl_FragCoord.xy*rblSoftDepthTexel).r);\n",
    "    float self = rblViewDepth(gl_FragCoord.z);\n",
    "    return clamp((scene - self)/rblSoftDepth.w, 0.0, 1.0);\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_surface[] = {
    "// Surface: what a shaded point is, in linear units. Filled by the material decode (material.glsl)\n",
    "// in forward and geometry passes, or from the G-buffer (gbuffer_read.glsl) in the deferred passes;\n",
    "// read by the lights (lights.glsl).\n",
    "#include \"common.glsl\"\n",
    "\n",
    "struct RblShadingPoint {\n",
    "    vec3 position;      // world\n",
    "    vec3 normal;        // unit, world\n",
    "    vec3 albedo;        // linear base colour\n",
    "    float specular;     // Blinn-Phong: specular intensity (the map, or 1: its colour holds the scale)\n",
    "    float roughness;    // GGX: perceptual roughness\n",
    "    float occlusion;    // ambient occlusion (indirect light only)\n",
    "    vec3 specularColor; // Blinn-Phong: linear specular colour (white in the G-buffer)\n",
    "    float shininess;    // Blinn-Phong exponent\n",
    "    float metalness;    // GGX\n",
    "    vec2 caster;        // identity of the billboard the point lies on (two bytes /255; 0 = a Model): its own caster never shadows it\n",
    "    vec3 face;          // unit normal of the rasterised surface (the card's plane, a Model's triangle), either sign: shadow biasing\n",
    "    float transmission; // share of the light on the card's back let through (transmission.glsl; 0 = none)\n",
    "};\n",
    NULL };
static const char *const rbl__shader_transmission[] = {
    "// Transmission: light through a thin card (leaves, paper, cloth) from a light on its other side. The\n",
    "// card is a thin diffuse sheet: of the irradiance reaching its back it lets through the share t\n",
    "// (the material's rblTransmission x (1 - thickness)) and spreads it diffusely over the front, in\n",
    "// its own colour (albedo). The back's cosine is wrapped by RBL_TRANSMISSION_WRAP: a light edge-on\n",
    "// to the card still shows through its rim, fading to nothing at N.L = wrap on the lit side.\n",
    "// Included by material.glsl (the uniform) and lights.glsl (the term); compiled only with:\n",
    "//   RBL_TRANSMISSION            RblLitShaderDesc.transmission (forward variants)\n",
    "//   RBL_THICKNESS_CHANNEL c     material texture component (3 b, 4 a) holding thickness 0..1\n",
    "#include \"surface.glsl\"\n",
    "\n",
    "#ifdef RBL_TRANSMISSION\n",
    "#define RBL_TRANSMISSION_WRAP 0.25\n",
    "uniform float rblTransmission;      // share of the back's light let through, 0..1 (0: the term costs one compare)\n",
    "\n",
    "// Radiance toward the viewer per unit irradiance (pi folded in, as rblBrdf) from a light at\n",
    "// cos(incidence) NdotL on the shaded side (negative: behind the card)\n",
    "vec3 rblTransmitted(RblShadingPoint s, float NdotL)\n",
    "{\n",
    "    float back = clamp((RBL_TRANSMISSION_WRAP - NdotL)/(1.0 + RBL_TRANSMISSION_WRAP), 0.0, 1.0);\n",
    "    return s.albedo*(s.transmission*back);\n",
    "}\n",
    "#endif\n",
    NULL };
static const char *const rbl__shader_volume_vs[] = {
    "// Deferred light volume, vertex stage: a sphere proxy per bounded point/spot light, one instanced\n",
    "// draw; the light's packed values ride along as instance attributes (as the forward uniforms).\n",
    "#include \"dialect.glsl\"\n",
    "\n",
    "RBL_ATTRIBUTE vec3 vertexPosition;                         // proxy that encloses the unit sphere\n",
    "layout(location = 10) in vec4 rblVolumePosition; // as rblLightPosition (w = 1)\n",
    "layout(location = 11) in vec4 rblVolumeColor;    // as rblLightColor (a = 1/range > 0)\n",
    "layout(location = 12) in vec4 rblVolumeSpot;     // as rblLightSpot\n",
    "layout(location = 13) in vec4 rblVolumeFalloff;  // xyz as rblLightAttenuation, w shadow map index + 1 (0 = none) + 8 x (relief bit + 1)\n",
    "uniform mat4 mvp;                               // projection x view of the geometry pass\n",
    "RBL_FLAT RBL_VARYING vec4 volumePosition;\n",
    "RBL_FLAT RBL_VARYING vec4 volumeColor;\n",
    "RBL_FLAT RBL_VARYING vec4 volumeSpot;\n",
    "RBL_FLAT RBL_VARYING vec4 volumeFalloff;\n",
    "\n",
    "void main()\n",
    "{\n",
    "    volumePosition = rblVolumePosition;\n",
    "    volumeColor = rblVolumeColor;\n",
    "    volumeSpot = rblVolumeSpot;\n",
    "    volumeFalloff = rblVolumeFalloff;\n",
    "    gl_Position = mvp*vec4(rblVolumePosition.xyz + vertexPosition/rblVolumeColor.a, 1.0);\n",
    "}\n",
    NULL };
// Every embedded shader by file name (tests compare these with shaders/*.glsl)
static const struct { const char *file; const char *const *source; } rbl__shaderFiles[] = {
    { "ambient.glsl", rbl__shader_ambient },
    { "common.glsl", rbl__shader_common },
    { "deferred_fullscreen.fs.glsl", rbl__shader_deferred_fullscreen_fs },
    { "deferred_resolve.fs.glsl", rbl__shader_deferred_resolve_fs },
    { "deferred_volume.fs.glsl", rbl__shader_deferred_volume_fs },
    { "dialect.glsl", rbl__shader_dialect },
    { "fullscreen.vs.glsl", rbl__shader_fullscreen_vs },
    { "gbuffer.fs.glsl", rbl__shader_gbuffer_fs },
    { "gbuffer_codec.glsl", rbl__shader_gbuffer_codec },
    { "gbuffer_read.glsl", rbl__shader_gbuffer_read },
    { "light_grid.glsl", rbl__shader_light_grid },
    { "lights.glsl", rbl__shader_lights },
    { "lit.fs.glsl", rbl__shader_lit_fs },
    { "lit.vs.glsl", rbl__shader_lit_vs },
    { "lit_instanced.vs.glsl", rbl__shader_lit_instanced_vs },
    { "material.glsl", rbl__shader_material },
    { "output.glsl", rbl__shader_output },
    { "relief.glsl", rbl__shader_relief },
    { "scene_composite.fs.glsl", rbl__shader_scene_composite_fs },
    { "scene_composite.vs.glsl", rbl__shader_scene_composite_vs },
    { "shadow_caster.fs.glsl", rbl__shader_shadow_caster_fs },
    { "shadow_tint.glsl", rbl__shader_shadow_tint },
    { "shadows.glsl", rbl__shader_shadows },
    { "skinning.glsl", rbl__shader_skinning },
    { "soft.glsl", rbl__shader_soft },
    { "surface.glsl", rbl__shader_surface },
    { "transmission.glsl", rbl__shader_transmission },
    { "volume.vs.glsl", rbl__shader_volume_vs },
};
// Each stage with its includes resolved, dependencies first (the loader joins these)
static const char *const *const rbl__pass_fullscreen_vs[] = { rbl__shader_dialect, rbl__shader_fullscreen_vs, NULL };
static const char *const *const rbl__pass_lit_vs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_skinning, rbl__shader_lit_vs, NULL };
static const char *const *const rbl__pass_lit_instanced_vs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_lit_instanced_vs, NULL };
static const char *const *const rbl__pass_scene_composite_vs[] = { rbl__shader_dialect, rbl__shader_scene_composite_vs, NULL };
static const char *const *const rbl__pass_volume_vs[] = { rbl__shader_dialect, rbl__shader_volume_vs, NULL };
static const char *const *const rbl__pass_deferred_fullscreen_fs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_surface, rbl__shader_gbuffer_codec, rbl__shader_gbuffer_read, rbl__shader_ambient, rbl__shader_shadows, rbl__shader_shadow_tint, rbl__shader_transmission, rbl__shader_light_grid, rbl__shader_lights, rbl__shader_deferred_fullscreen_fs, NULL };
static const char *const *const rbl__pass_deferred_resolve_fs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_surface, rbl__shader_gbuffer_codec, rbl__shader_gbuffer_read, rbl__shader_ambient, rbl__shader_output, rbl__shader_deferred_resolve_fs, NULL };
static const char *const *const rbl__pass_deferred_volume_fs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_surface, rbl__shader_gbuffer_codec, rbl__shader_gbuffer_read, rbl__shader_ambient, rbl__shader_shadows, rbl__shader_shadow_tint, rbl__shader_transmission, rbl__shader_light_grid, rbl__shader_lights, rbl__shader_deferred_volume_fs, NULL };
static const char *const *const rbl__pass_gbuffer_fs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_surface, rbl__shader_transmission, rbl__shader_relief, rbl__shader_material, rbl__shader_gbuffer_codec, rbl__shader_gbuffer_fs, NULL };
static const char *const *const rbl__pass_lit_fs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_surface, rbl__shader_transmission, rbl__shader_relief, rbl__shader_material, rbl__shader_ambient, rbl__shader_shadows, rbl__shader_shadow_tint, rbl__shader_light_grid, rbl__shader_lights, rbl__shader_output, rbl__shader_soft, rbl__shader_lit_fs, NULL };
static const char *const *const rbl__pass_scene_composite_fs[] = { rbl__shader_dialect, rbl__shader_scene_composite_fs, NULL };
static const char *const *const rbl__pass_shadow_caster_fs[] = { rbl__shader_dialect, rbl__shader_common, rbl__shader_surface, rbl__shader_transmission, rbl__shader_relief, rbl__shader_material, rbl__shader_shadow_caster_fs, NULL };
static const struct { const char *file; const char *const *const *parts; } rbl__passFiles[] = {
    { "fullscreen.vs.glsl", rbl__pass_fullscreen_vs },
    { "lit.vs.glsl", rbl__pass_lit_vs },
    { "lit_instanced.vs.glsl", rbl__pass_lit_instanced_vs },
    { "scene_composite.vs.glsl", rbl__pass_scene_composite_vs },
    { "volume.vs.glsl", rbl__pass_volume_vs },
    { "deferred_fullscreen.fs.glsl", rbl__pass_deferred_fullscreen_fs },
    { "deferred_resolve.fs.glsl", rbl__pass_deferred_resolve_fs },
    { "deferred_volume.fs.glsl", rbl__pass_deferred_volume_fs },
    { "gbuffer.fs.glsl", rbl__pass_gbuffer_fs },
    { "lit.fs.glsl", rbl__pass_lit_fs },
    { "scene_composite.fs.glsl", rbl__pass_scene_composite_fs },
    { "shadow_caster.fs.glsl", rbl__pass_shadow_caster_fs },
};
// RBL-SHADERS-END

//----------------------------------------------------------------------------------
// Module Internal Functions: small vector helpers (C and C++ without compound literals)   >>vec
//----------------------------------------------------------------------------------
static inline Vector3 rbl__v3(float x, float y, float z) { Vector3 v; v.x = x; v.y = y; v.z = z; return v; }
static inline bool rbl__finite(float x) { return (x == x) && (x - x == 0.0f); }    // false for NaN and +-Inf
static inline bool rbl__finite3(Vector3 v) { return rbl__finite(v.x) && rbl__finite(v.y) && rbl__finite(v.z); }
// Below 2^60 (1.2e18) so that squared lengths and differences stay finite in float
static inline bool rbl__bounded3(Vector3 v) { return (fabsf(v.x) < 1.15e18f) && (fabsf(v.y) < 1.15e18f) && (fabsf(v.z) < 1.15e18f); }
static inline bool rbl__unit3(Vector3 v) { return rbl__finite3(v) && (fabsf(v.x*v.x + v.y*v.y + v.z*v.z - 1.0f) < 1e-3f); }
// A camera the frame and matrix code can use: bounded finite vectors, fovy in (0, 180) for a
// perspective camera (any finite positive height for an orthographic one), a known projection
static inline bool rbl__cameraOk(Camera3D c)
{
    if (!rbl__bounded3(c.position) || !rbl__bounded3(c.target) || !rbl__bounded3(c.up)) return false;
    if (c.projection == CAMERA_PERSPECTIVE) return (c.fovy > 0.0f) && (c.fovy < 180.0f);
    return (c.projection == CAMERA_ORTHOGRAPHIC) && (c.fovy > 0.0f) && (c.fovy < 1.15e18f);
}
// None of n floats stored from f on has |value| >= 2^(limitExponent - 127) (NaN and Inf included):
// adding 256 - limitExponent to the exponent field carries into the sign bit exactly for those, so
// one OR over all of them decides. Branch-free (per-float tests were a chain of branches).
static inline bool rbl__exponentsBelow(const void *f, int n, unsigned int limitExponent)
{
    const unsigned int bias = (256u - limitExponent) << 23;
    unsigned int carry = 0;
    for (int i = 0; i < n; i++)
    {
        unsigned int u;
        memcpy(&u, (const unsigned char *)f + (size_t)i*sizeof(u), sizeof(u));
        carry |= (u & 0x7f800000u) + bias;
    }
    return (carry & 0x80000000u) == 0;
}
// None of n floats stored from f on is NaN or Inf (exponent field 255)
static inline bool rbl__allFinite(const void *f, int n) { return rbl__exponentsBelow(f, n, 255u); }
// Billboard positions, sizes, origins and source rectangles: below 2^60 (exponent 127 + 60)
#define RBL__BILLBOARD_LIMIT_EXPONENT 187u
// Instance floats and any rotation: values of 2^120 (1.3e36, exponent field 127 + 120) or more could
// overflow float once the GPU combines them: rejected like NaN
#define RBL__INSTANCE_LIMIT_EXPONENT 247u
// CAMERA_PLANE's caller up, whose length scales the quad's height (as raylib's): below 2^30
#define RBL__UP_LIMIT_EXPONENT 157u
// Largest texture side a billboard's frame may come from
#define RBL__MAX_TEXTURE_SIDE 65536
static inline float rbl__len2(Vector3 v) { return v.x*v.x + v.y*v.y + v.z*v.z; }
// The same bits (a cache key: -0 and 0, NaNs told apart), without a library call per billboard
static inline bool rbl__sameBits3(const Vector3 *a, const Vector3 *b)
{
    unsigned int x[3], y[3];
    memcpy(x, a, sizeof(x));
    memcpy(y, b, sizeof(y));
    return ((x[0] ^ y[0]) | (x[1] ^ y[1]) | (x[2] ^ y[2])) == 0u;
}
static inline float rbl__dot(Vector3 a, Vector3 b) { return a.x*b.x + a.y*b.y + a.z*b.z; }
static inline Vector3 rbl__sub(Vector3 a, Vector3 b) { return rbl__v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline Vector3 rbl__neg(Vector3 a) { return rbl__v3(-a.x, -a.y, -a.z); }
static inline Vector3 rbl__cross(Vector3 a, Vector3 b) { return rbl__v3(a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x); }

// a*b exactly as raymath's MatrixMultiply (raymath is not included: it does not compile
// warning-free as C++ with -Wextra). Matrix fields are named m0..m15 but stored row by row.
static void rbl__matToArray(Matrix m, float a[16])
{
    a[0] = m.m0; a[1] = m.m1; a[2] = m.m2; a[3] = m.m3; a[4] = m.m4; a[5] = m.m5; a[6] = m.m6; a[7] = m.m7;
    a[8] = m.m8; a[9] = m.m9; a[10] = m.m10; a[11] = m.m11; a[12] = m.m12; a[13] = m.m13; a[14] = m.m14; a[15] = m.m15;
}

static Matrix rbl__matFromArray(const float a[16])
{
    Matrix m;
    m.m0 = a[0]; m.m1 = a[1]; m.m2 = a[2]; m.m3 = a[3]; m.m4 = a[4]; m.m5 = a[5]; m.m6 = a[6]; m.m7 = a[7];
    m.m8 = a[8]; m.m9 = a[9]; m.m10 = a[10]; m.m11 = a[11]; m.m12 = a[12]; m.m13 = a[13]; m.m14 = a[14]; m.m15 = a[15];
    return m;
}

static Matrix rbl__matMul(Matrix left, Matrix right)
{
    float a[16], b[16], r[16];
    rbl__matToArray(left, a);
    rbl__matToArray(right, b);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r[i*4 + j] = a[i*4 + 0]*b[0*4 + j] + a[i*4 + 1]*b[1*4 + j] + a[i*4 + 2]*b[2*4 + j] + a[i*4 + 3]*b[3*4 + j];
    return rbl__matFromArray(r);
}

static Matrix rbl__identity(void)
{
    Matrix m;
    memset(&m, 0, sizeof(m));
    m.m0 = m.m5 = m.m10 = m.m15 = 1.0f;
    return m;
}

// Back to framebuffer fbo with a viewport covering it. rlgl's framebuffer size is the last render
// texture's after EndTextureMode (raylib does not reset it), so the screen's size comes from the
// window when there is one (headless rlglInit contexts have none: rlgl's size is the screen's there)
// The framebuffer draws go to now. raylib 6.0's rlGetActiveFramebuffer asks for the ES 3 name of
// the binding and answers 0 on ES 2 / WebGL1: there GL is asked for the ES 2 one
typedef void (RBL__GLAPI *rbl__GlGetIntegerv)(unsigned int pname, int *data);
static unsigned int rbl__activeFramebuffer(void)
{
    if ((rbl__glsl() != 100) || (rlGetTextureIdDefault() == 0)) return rlGetActiveFramebuffer();
    void *proc = rlGetProcAddress("glGetIntegerv");
    if (proc == NULL) return 0;
    rbl__GlGetIntegerv get;
    memcpy(&get, &proc, sizeof(get));
    int fbo = 0;
    get(0x8CA6 /* GL_FRAMEBUFFER_BINDING */, &fbo);
    return (fbo > 0)? (unsigned int)fbo : 0u;
}

// GL_MAX_DRAW_BUFFERS of the context (0 without GLSL 3 or the entry point): the G-buffer's thin
// target is a 5th colour target (ES 3 and WebGL2 promise 4)
static int rbl__maxDrawBuffers(void)
{
    if ((rbl__glsl() < 300) || (rlGetTextureIdDefault() == 0)) return 0;
    if (RBL__HOOK(gbufferFourDrawBuffers)) return 4;
    void *proc = rlGetProcAddress("glGetIntegerv");
    if (proc == NULL) return 0;
    rbl__GlGetIntegerv get;
    memcpy(&get, &proc, sizeof(get));
    int n = 0;
    get(0x8824 /* GL_MAX_DRAW_BUFFERS */, &n);
    return n;
}

// Size of the target draws go to now: inside BeginTextureMode rlgl's framebuffer size (the
// texture's); on the screen raylib's render size (rlgl keeps the last texture's after EndTextureMode
// and never hears of window resizes), or rlgl's where there is no raylib window (headless contexts)
static void rbl__targetSize(unsigned int fbo, int *w, int *h)
{
    *w = rlGetFramebufferWidth(); *h = rlGetFramebufferHeight();
    if ((fbo == 0) && (GetRenderWidth() > 0) && (GetRenderHeight() > 0)) { *w = GetRenderWidth(); *h = GetRenderHeight(); }
}

static void rbl__restoreTarget(unsigned int fbo)
{
    int w, h;
    rbl__targetSize(fbo, &w, &h);
    if (fbo != 0) rlEnableFramebuffer(fbo);
    else rlDisableFramebuffer();
    rlViewport(0, 0, w, h);
}

// Unit vector or false when v is too short to give a direction
static inline bool rbl__normalizeTo(Vector3 v, Vector3 *out)
{
    float l2 = rbl__len2(v);
    if (!(l2 > 1e-24f) || !rbl__finite(l2)) return false;
    float inv = 1.0f/sqrtf(l2);
    *out = rbl__v3(v.x*inv, v.y*inv, v.z*inv);
    return true;
}

// World axis standing in for an up vector parallel to d: -Z (raylib's forward, "north") for d
// along +Y, so a camera looking straight down keeps -Z as screen-up, +Z along -Y, +Y for d along X
// or Z. Chosen by d's largest component, which stays put near every axis (the least aligned axis
// flips between two when d is near an axis, where the fallback is used).
static Vector3 rbl__fallbackUp(Vector3 d)
{
    float ax = fabsf(d.x), ay = fabsf(d.y), az = fabsf(d.z);
    if ((ay >= ax) && (ay >= az)) return rbl__v3(0.0f, 0.0f, (d.y > 0.0f)? -1.0f : 1.0f);
    return rbl__v3(0.0f, 1.0f, 0.0f);
}

// Unit component of v perpendicular to unit n; false if v is (nearly) parallel to n
static inline bool rbl__perpendicular(Vector3 v, Vector3 n, Vector3 *out)
{
    float d = rbl__dot(v, n);
    Vector3 p = rbl__v3(v.x - n.x*d, v.y - n.y*d, v.z - n.z*d);
    float l2v = rbl__len2(v);
    if (!(rbl__len2(p) > 1e-10f*l2v)) return false;     // relative test: scale-free
    return rbl__normalizeTo(p, out);
}

// Near-degenerate frames. Float gives the direction of v's component off an axis n only to about
// 6e-8/s (s = sine of the angle between v and n; the GPU's rounding differs from the CPU's), so a
// frame direction taken from v is blended with a fallback's where s is small:
//     unit(w unit(v off n) + (1 - w) unit(f off n)),  w = smoothstep(RBL__BLEND_LO, RBL__BLEND_HI, s)
// v alone at s >= 1/8 (7.2 degrees), the fallback f alone at s <= 1/64 (0.9 degrees), continuous in
// between (the two directions cancel only on the side where v's points away from f's, at w = 1/2).
#define RBL__BLEND_LO 0.015625f
#define RBL__BLEND_HI 0.125f

// smoothstep(RBL__BLEND_LO, RBL__BLEND_HI, s)
static inline float rbl__blendWeight(float s)
{
    float t = (s - RBL__BLEND_LO)*(1.0f/(RBL__BLEND_HI - RBL__BLEND_LO));
    t = fminf(fmaxf(t, 0.0f), 1.0f);
    return t*t*(3.0f - 2.0f*t);
}

// Weight of v's own direction off unit n (1 well off n; 0 along n or for v shorter than 1e-12) and
// v's component off n (*vp)
static inline float rbl__offAxis(Vector3 v, Vector3 n, Vector3 *vp)
{
    float d = rbl__dot(v, n);
    *vp = rbl__v3(v.x - n.x*d, v.y - n.y*d, v.z - n.z*d);
    float vv = rbl__len2(v), pp = rbl__len2(*vp);
    if (!(vv > 1e-24f)) return 0.0f;
    if (pp >= (RBL__BLEND_HI*RBL__BLEND_HI)*vv) return 1.0f;
    return rbl__blendWeight(sqrtf(pp/vv));
}

// Unit direction perpendicular to unit n: vp's (from rbl__offAxis) at w = 1, the fallback f's
// component off n at w = 0 (f must stand well off n), the blend between, projected off n again,
// twice: the blended directions are each perpendicular to n only to 6e-8/s, and where they nearly
// cancel that residue is most of what is left
static inline Vector3 rbl__blendOffAxis(Vector3 vp, float w, Vector3 f, Vector3 n)
{
    Vector3 c = rbl__v3(0.0f, 0.0f, 0.0f);
    if (w > 0.0f)
    {
        float k = w/sqrtf(rbl__len2(vp));
        c = rbl__v3(vp.x*k, vp.y*k, vp.z*k);
        if (w >= 1.0f) return c;
    }
    float d = rbl__dot(f, n);
    Vector3 fp = rbl__v3(f.x - n.x*d, f.y - n.y*d, f.z - n.z*d);
    float kf = (1.0f - w)/sqrtf(rbl__len2(fp));
    c = rbl__v3(c.x + fp.x*kf, c.y + fp.y*kf, c.z + fp.z*kf);
    for (int i = 0; i < 2; i++)
    {
        d = rbl__dot(c, n);
        c = rbl__v3(c.x - n.x*d, c.y - n.y*d, c.z - n.z*d);
    }
    if (!(rbl__len2(c) > 1e-24f)) c = fp;      // exactly at the cancelling point
    float kc = 1.0f/sqrtf(rbl__len2(c));
    return rbl__v3(c.x*kc, c.y*kc, c.z*kc);
}

//----------------------------------------------------------------------------------
// Module Functions Definition: geometry   >>geometry
//----------------------------------------------------------------------------------
// Camera frame as raymath's MatrixLookAt builds it, in double: the float inputs subtract and
// multiply exactly there, so the frame is right to float however close camera.up comes to the view
// (raylib's float frame is off by 6e-8/s there, and not orthonormal). Near-degenerate blend as for
// billboards, over s from 1e-6 (the old hard threshold) to 1e-5: only cameras whose float frame is
// already noise above 0.3 degrees notice it.
#define RBL__CAMERA_BLEND_LO 1e-6
#define RBL__CAMERA_BLEND_HI 1e-5
// (the public RblGetCameraFrame checks the camera first; the header's own light cameras have no fovy)
static RblCameraFrame rbl__cameraFrame(Camera3D camera)
{
    RblCameraFrame view;
    view.eye = camera.position;
    double b[3] = { (double)camera.position.x - camera.target.x, (double)camera.position.y - camera.target.y, (double)camera.position.z - camera.target.z };
    double bb = b[0]*b[0] + b[1]*b[1] + b[2]*b[2];
    if (!(bb > 1e-24) || !(bb < 1e300)) { b[0] = 0.0; b[1] = 0.0; b[2] = 1.0; bb = 1.0; }
    double inv = 1.0/sqrt(bb);
    for (int i = 0; i < 3; i++) b[i] *= inv;
    // Up off the view; its weight against the fallback by the sine s between camera.up and the view
    double u[3] = { camera.up.x, camera.up.y, camera.up.z };
    if (!rbl__finite3(camera.up)) u[0] = u[1] = u[2] = 0.0;
    double d = u[0]*b[0] + u[1]*b[1] + u[2]*b[2];
    double p[3] = { u[0] - b[0]*d, u[1] - b[1]*d, u[2] - b[2]*d };
    double uu = u[0]*u[0] + u[1]*u[1] + u[2]*u[2], pp = p[0]*p[0] + p[1]*p[1] + p[2]*p[2];
    double w = 0.0;
    if (uu > 1e-24)
    {
        double t = (sqrt(pp/uu) - RBL__CAMERA_BLEND_LO)/(RBL__CAMERA_BLEND_HI - RBL__CAMERA_BLEND_LO);
        t = (t < 0.0)? 0.0 : ((t > 1.0)? 1.0 : t);
        w = t*t*(3.0 - 2.0*t);
    }
    double c[3] = { 0.0, 0.0, 0.0 };
    if (w > 0.0) { double k = w/sqrt(pp); for (int i = 0; i < 3; i++) c[i] = p[i]*k; }
    if (w < 1.0)
    {
        Vector3 fv = rbl__fallbackUp(rbl__v3((float)b[0], (float)b[1], (float)b[2]));
        double f[3] = { fv.x, fv.y, fv.z };
        double df = f[0]*b[0] + f[1]*b[1] + f[2]*b[2];
        for (int i = 0; i < 3; i++) f[i] -= b[i]*df;
        double k = (1.0 - w)/sqrt(f[0]*f[0] + f[1]*f[1] + f[2]*f[2]);
        for (int i = 0; i < 3; i++) c[i] += f[i]*k;
        for (int pass = 0; pass < 2; pass++)
        {
            double dc = c[0]*b[0] + c[1]*b[1] + c[2]*b[2];
            for (int i = 0; i < 3; i++) c[i] -= b[i]*dc;
        }
        double cc = c[0]*c[0] + c[1]*c[1] + c[2]*c[2];
        if (!(cc > 1e-30)) { for (int i = 0; i < 3; i++) c[i] = f[i]; cc = f[0]*f[0] + f[1]*f[1] + f[2]*f[2]; }   // exactly at the cancelling point
        double kc = 1.0/sqrt(cc);
        for (int i = 0; i < 3; i++) c[i] *= kc;
    }
    // right = up x back, up = back x right (both unit: c is unit and perpendicular to back)
    double r[3] = { c[1]*b[2] - c[2]*b[1], c[2]*b[0] - c[0]*b[2], c[0]*b[1] - c[1]*b[0] };
    view.right = rbl__v3((float)r[0], (float)r[1], (float)r[2]);
    view.up = rbl__v3((float)(b[1]*r[2] - b[2]*r[1]), (float)(b[2]*r[0] - b[0]*r[2]), (float)(b[0]*r[1] - b[1]*r[0]));
    view.back = rbl__v3((float)b[0], (float)b[1], (float)b[2]);
    view.orthographic = (camera.projection == CAMERA_ORTHOGRAPHIC);
    return view;
}

RblCameraFrame RblGetCameraFrame(Camera3D camera)
{
    if (!rbl__cameraOk(camera))
    {
        TraceLog(LOG_WARNING, "RBL: RblGetCameraFrame: camera with NaN/Inf or huge fields, fovy outside (0, 180) or unknown projection; identity frame returned");
        RblCameraFrame view = { { 0.0f, 0.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { 0.0f, 1.0f, 0.0f }, { 0.0f, 0.0f, 1.0f }, false };
        return view;
    }
    return rbl__cameraFrame(camera);
}

// sin and cos of an angle in degrees. The reduction to [-45, 45] is exact in degrees (multiples of 90
// come out exact: cos 90 = 0, where cosf(90*DEG2RAD) = -4.4e-8), then Cephes' minimax polynomials for
// [-pi/4, pi/4]: within 1e-7 of the double result (tested), and no libm call in the per-billboard path.
static void rbl__sinCosDeg(float degrees, float *sinOut, float *cosOut)
{
    if (fabsf(degrees) > 360.0f*1024.0f) degrees = fmodf(degrees, 360.0f);     // fmodf is exact
    int q = (int)(degrees*(1.0f/90.0f) + copysignf(0.5f, degrees));           // nearest quadrant
    float x = (degrees - (float)q*90.0f)*(PI/180.0f);  // exact subtraction for |degrees| <= 368640
    float x2 = x*x;
    float sn = x + x*x2*(-1.6666654611e-1f + x2*(8.3321608736e-3f + x2*(-1.9515295891e-4f)));
    float cs = 1.0f - 0.5f*x2 + x2*x2*(4.166664568298827e-2f + x2*(-1.388731625493765e-3f + x2*2.443315711809948e-5f));
    // Quadrant q: (sin, cos) = (sn, cs), (cs, -sn), (-sn, -cs), (-cs, sn), chosen without branches
    // (random rotations mispredict a switch)
    unsigned int us, uc, swap = 0u - (unsigned int)(q & 1);
    memcpy(&us, &sn, sizeof(us));
    memcpy(&uc, &cs, sizeof(uc));
    unsigned int rs = ((us & ~swap) | (uc & swap)) ^ ((unsigned int)(q & 2) << 30);
    unsigned int rc = ((uc & ~swap) | (us & swap)) ^ ((unsigned int)((q + 1) & 2) << 30);
    memcpy(sinOut, &rs, sizeof(rs));
    memcpy(cosOut, &rc, sizeof(rc));
}

// A caller's direction (FIXED up and normal, AXIS axis) from any finite vector: a long one is scaled
// by a power of two (exact) so its squared length cannot overflow; short ones are left (shorter than
// 1e-12 counts as zero)
static inline Vector3 rbl__tame(Vector3 v)
{
    if (!((fabsf(v.x) > 1e12f) || (fabsf(v.y) > 1e12f) || (fabsf(v.z) > 1e12f))) return v;     // the usual case: no library call
    float m = fmaxf(fabsf(v.x), fmaxf(fabsf(v.y), fabsf(v.z)));
    int e;
    frexpf(m, &e);
    return rbl__v3(ldexpf(v.x, -e), ldexpf(v.y, -e), ldexpf(v.z, -e));
}

// The facing a billboard casts with: in an omni pass with light-facing casters CAMERA_PLANE cards
// turn toward the light (no view plane is common to the six faces)
static inline int rbl__castFacing(const rbl__Cast *cast, int facing)
{
    return ((cast != NULL) && cast->radial && (facing == RBL_FACING_CAMERA_PLANE))? RBL_FACING_CAMERA_POSITION : facing;
}

// Right, up (both scaled to unit length except CAMERA_PLANE's caller up) and unit normal. Every mode
// takes one direction off an axis from a vector v, blended toward a fallback f where v nears the axis
// (README "Degenerate frames"): the first switch picks the three, one blend follows, the second switch builds
// the frame (one blend, not one per mode: llvmpipe runs every branch of the GLSL twin).
static void rbl__facingBasis(const RblCameraFrame *view, const rbl__Cast *cast, const RblBillboard *b, Vector3 *right, Vector3 *up, Vector3 *normal)
{
    Vector3 r = view->right, u = view->up, n = view->back;
    Vector3 axis = r, v = u, f = u, a = rbl__v3(0.0f, 1.0f, 0.0f);
    Vector3 toEye = view->orthographic? view->back : rbl__sub(view->eye, b->position);     // a parallel view's eye is at infinity (a directional light's too)
    bool own = true;        // false: CAMERA_PLANE without an up, CAMERA_POSITION at the eye (the view's frame)
    int facing = rbl__castFacing(cast, b->facing);
    switch (facing)
    {
        // normal = right x (the caller's up off right), toward the camera's up
        case RBL_FACING_CAMERA_PLANE: own = rbl__len2(b->up) > 1e-24f; v = b->up; break;
        // n toward the eye; up = the camera's up off n, toward n x right (the centre on the camera's up line)
        case RBL_FACING_CAMERA_POSITION: own = rbl__normalizeTo(toEye, &axis); f = rbl__cross(axis, r); break;
        // n = toward the eye off the axis, toward the view's back off the axis, itself toward the view's
        // up off the axis where the view looks along it (up and back are never both near it)
        case RBL_FACING_AXIS:
        {
            Vector3 given = rbl__tame(b->axis);
            if (rbl__len2(given) > 1e-24f) rbl__normalizeTo(given, &a);    // shorter counts as zero (a GPU may flush it)
            Vector3 q;
            float wb = rbl__offAxis(view->back, a, &q);
            axis = a; v = toEye; f = rbl__blendOffAxis(q, wb, view->up, a);
        } break;
        // up off the normal, toward the normal's fallback up
        case RBL_FACING_FIXED:
        {
            Vector3 normal = rbl__tame(b->axis), up = rbl__tame(b->up);
            axis = rbl__v3(0.0f, 0.0f, 1.0f);
            if (rbl__len2(normal) > 1e-24f) rbl__normalizeTo(normal, &axis);
            v = (rbl__len2(up) > 1e-24f)? up : rbl__v3(0.0f, 1.0f, 0.0f); f = rbl__fallbackUp(axis);
        } break;
        default: own = false; break;
    }
    if (!own) { *right = r; *up = u; *normal = n; return; }
    Vector3 p;
    float w = rbl__offAxis(v, axis, &p);
    Vector3 d = rbl__blendOffAxis(p, w, f, axis);
    switch (facing)
    {
        case RBL_FACING_CAMERA_PLANE:
        {
            // raylib scales the caller's up as given (not normalised): keep that for parity. Blended, the
            // up keeps its length and its part along right and turns its part off right to d (the quad
            // stays flat, and collapses as raylib's does with up along right)
            n = rbl__cross(r, d);
            u = b->up;
            if (w < 1.0f)
            {
                float along = rbl__dot(b->up, r), off = sqrtf(rbl__len2(p));
                u = rbl__v3(r.x*along + d.x*off, r.y*along + d.y*off, r.z*along + d.z*off);
            }
        } break;
        case RBL_FACING_CAMERA_POSITION: n = axis; u = d; r = rbl__cross(u, n); break;
        case RBL_FACING_AXIS:
        {
            Vector3 nn = d;
            u = a; n = nn; r = rbl__cross(u, n);
            // Shadow pass: tilt about r (rbl__billboardVertices keeps the quad's lowest edge in place),
            // by the smallest angle t at which the light sees the quad at the minimum angle s: in the
            // (n, a) plane with l's components x = n.l, y = |a.l|, rho = |(x, y)|, (cos t, sin t) = k
            // (x, y)/rho + sqrt(1 - k^2) (y, -x)/rho, k = min(s/rho, 1) (no inverse trig: CPU and GPU
            // agree). Light-facing casters turn their front face to the light (x signed: continuous as
            // the light passes over the axis); camera-facing ones whichever face is nearer (x = |n.l|:
            // the lean changes side where the light crosses the card's plane). An upright sprite thus
            // still casts under a light along its axis. r stays; n and u turn together.
            Vector3 l;
            if ((cast != NULL) && (cast->minSin > 0.0f) &&
                rbl__normalizeTo(rbl__v3(cast->light.x - b->position.x*cast->light.w, cast->light.y - b->position.y*cast->light.w,
                                         cast->light.z - b->position.z*cast->light.w), &l))
            {
                float ln = rbl__dot(l, n), la = rbl__dot(l, a);
                float x = cast->faceLight? ln : fabsf(ln), y = fabsf(la), rho = sqrtf(x*x + y*y);
                if ((x < cast->minSin) && (rho > 0.0f))
                {
                    float k = fminf(cast->minSin/rho, 1.0f), m = sqrtf(1.0f - k*k);
                    float sg = cast->faceLight? ((la >= 0.0f)? 1.0f : -1.0f) : (((ln >= 0.0f) == (la >= 0.0f))? 1.0f : -1.0f);
                    float c = (k*x + m*y)/rho, sn = (k*y - m*x)/rho*sg;
                    // rho is the sine between l and the pivot line, where no tilt helps and (x, y)/rho is
                    // float noise: the tilt fades out with the near-degenerate blend weight (c >= 0: no cancelling)
                    float wt = rbl__blendWeight(rho);
                    if (wt < 1.0f)
                    {
                        c = c*wt + (1.0f - wt); sn = sn*wt;
                        float inv = 1.0f/sqrtf(c*c + sn*sn);
                        c *= inv; sn *= inv;
                    }
                    n = rbl__v3(nn.x*c + a.x*sn, nn.y*c + a.y*sn, nn.z*c + a.z*sn);
                    u = rbl__v3(a.x*c - nn.x*sn, a.y*c - nn.y*sn, a.z*c - nn.z*sn);
                }
            }
        } break;
        default: n = axis; u = d; r = rbl__cross(u, n); break;      // RBL_FACING_FIXED
    }
    *right = r; *up = u; *normal = n;
}

// The facing frame of b, from the cache when it holds b's (CAMERA_PLANE: same up), else made and kept.
// Made exactly as rbl__facingBasis(); a caller up is normalised here and its length kept (raylib
// scales the quad's height by it).
static void rbl__facingFrame(const RblCameraFrame *view, const rbl__Cast *cast, const RblBillboard *b, rbl__FrameCache *cache)
{
    int facing = rbl__castFacing(cast, b->facing);
    if ((cache->facing == RBL_FACING_CAMERA_PLANE) && (facing == RBL_FACING_CAMERA_PLANE) && rbl__sameBits3(&cache->key, &b->up)) return;
    Vector3 R, U, N;
    rbl__facingBasis(view, cast, b, &R, &U, &N);
    float ulen = 1.0f;
    if ((facing == RBL_FACING_CAMERA_PLANE) && (rbl__len2(b->up) > 0.0f))
    {
        ulen = sqrtf(rbl__len2(U));
        if (ulen > 0.0f) U = rbl__v3(U.x/ulen, U.y/ulen, U.z/ulen);
    }
    cache->key = b->up;
    cache->right = R; cache->up = U; cache->normal = N;
    cache->normalXRight = rbl__cross(N, R);
    cache->normalXUp = rbl__cross(N, U);
    cache->upLength = ulen;
    cache->facing = facing;
}

// The albedo texture's size; an empty slot draws raylib's 1x1 default texture
static void rbl__albedoSize(const Material *material, int *width, int *height)
{
    const bool has = (material->maps != NULL) && (material->maps[MATERIAL_MAP_ALBEDO].texture.id != 0);
    *width = has? material->maps[MATERIAL_MAP_ALBEDO].texture.width : 1;
    *height = has? material->maps[MATERIAL_MAP_ALBEDO].texture.height : 1;
}

// A billboard every path can expand: position .. source and up .. roundness are runs of floats
// (checked at compile time), below 2^60 so that corners (position + size along unit axes), eye
// distances and texcoords (source edges / texture size) stay finite; a known facing; a texture of
// 1..65536 texels
// The batch's fade stream: per vertex the second frame's texture coordinate, weight, axes code
// (location 5) and both frames' clip positions (rblFadeClip); four vertices a billboard
#define RBL__FADE_VERTEX_FLOATS 8
#define RBL__FADE_FLOATS (4*RBL__FADE_VERTEX_FLOATS)
// A cross-fade: weight 0..1, the second frame's rectangle below the bound (limitExponent)
// and each clip rectangle zero or inside 2^-20 <= width, height <= 2^20, |x|, |y| <= 2^20 (the
// shaders divide by the extents)
static bool rbl__fadeOk(const RblFade *f, unsigned int limitExponent)
{
    for (int k = 0; k < 2; k++)
    {
        const Rectangle c = f->clip[k];
        if ((c.x == 0.0f) && (c.y == 0.0f) && (c.width == 0.0f) && (c.height == 0.0f)) continue;
        const float big = 1048576.0f, small = 1.0f/1048576.0f;
        if (!((fabsf(c.x) <= big) && (fabsf(c.y) <= big) && (c.width >= small) && (c.width <= big) && (c.height >= small) && (c.height <= big))) return false;
    }
    return rbl__finite(f->weight) && (f->weight >= 0.0f) && (f->weight <= 1.0f) && rbl__exponentsBelow(&f->source, 4, limitExponent);
}

// A billboard's words position .. roundness (0..20) each against its bound: the exponent field of
// float word i must stay below its limit e, which (field + 256 - e) << 23 carries into bit 31. Rotation
// is reduced exactly (fmod), so it may be as large as an instance's (2^120); up, axis and roundness
// need only be finite, but CAMERA_PLANE's up scales the quad's height by its length (as raylib) and
// is bounded like a size. Tint and facing (words 12, 13) are not floats: masked out
#define RBL__BIAS(e) ((256u - (e)) << 23)
#define RBL__BB RBL__BIAS(RBL__BILLBOARD_LIMIT_EXPONENT)
#define RBL__BF RBL__BIAS(255u)
#define RBL__BU RBL__BIAS(RBL__UP_LIMIT_EXPONENT)
#define RBL__EXP 0x7f800000u
static const unsigned int rbl__billboardWordMask[21] = { RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP,
    RBL__EXP, RBL__EXP, 0u, 0u, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP, RBL__EXP };
static const unsigned int rbl__billboardWordBias[2][21] = {
    { RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BIAS(RBL__INSTANCE_LIMIT_EXPONENT), RBL__BB, RBL__BB, RBL__BB, RBL__BB, 0u, 0u,
      RBL__BF, RBL__BF, RBL__BF, RBL__BF, RBL__BF, RBL__BF, RBL__BF },           // other facings: up, axis and roundness finite
    { RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BB, RBL__BIAS(RBL__INSTANCE_LIMIT_EXPONENT), RBL__BB, RBL__BB, RBL__BB, RBL__BB, 0u, 0u,
      RBL__BU, RBL__BU, RBL__BU, RBL__BF, RBL__BF, RBL__BF, RBL__BF } };         // CAMERA_PLANE: up bounded
#undef RBL__BIAS
#undef RBL__BB
#undef RBL__BF
#undef RBL__BU
#undef RBL__EXP

// The words' check one at a time (the reference of the four-lane one below, and where there is none)
static inline bool rbl__billboardWordsOkScalar(const RblBillboard *b)
{
    const unsigned int *bias = rbl__billboardWordBias[b->facing == RBL_FACING_CAMERA_PLANE];
    unsigned int word[21], carry = 0u;
    memcpy(word, b, sizeof(word));
    for (int i = 0; i < 21; i++) carry |= (word[i] & rbl__billboardWordMask[i]) + bias[i];
    return (carry & 0x80000000u) == 0u;
}

RBL__FORCE_INLINE bool rbl__billboardWordsOk(const RblBillboard *b)
{
#if defined(RBL__SSE2)
    const unsigned int *bias = rbl__billboardWordBias[b->facing == RBL_FACING_CAMERA_PLANE];
    const unsigned char *w = (const unsigned char *)b;
    __m128i carry = _mm_setzero_si128();
    for (int k = 0; k < 5; k++)
    {
        __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(w + 16*k));
        __m128i m = _mm_loadu_si128((const __m128i *)(const void *)(rbl__billboardWordMask + 4*k));
        carry = _mm_or_si128(carry, _mm_add_epi32(_mm_and_si128(v, m), _mm_loadu_si128((const __m128i *)(const void *)(bias + 4*k))));
    }
    unsigned int last;
    memcpy(&last, w + 80, sizeof(last));
    return (_mm_movemask_ps(_mm_castsi128_ps(carry)) == 0) && ((((last & rbl__billboardWordMask[20]) + bias[20]) & 0x80000000u) == 0u);
#else
    return rbl__billboardWordsOkScalar(b);
#endif
}

static inline bool rbl__billboardOk(const RblBillboard *b, int textureWidth, int textureHeight)
{
    if ((textureWidth <= 0) || (textureHeight <= 0) || (textureWidth > RBL__MAX_TEXTURE_SIDE) || (textureHeight > RBL__MAX_TEXTURE_SIDE)) return false;
    return (b->facing >= RBL_FACING_CAMERA_PLANE) && (b->facing <= RBL_FACING_FIXED) && rbl__billboardWordsOk(b);
}

// A frame's +U (t) and +V (v) in the quad's (right, up) plane, for its mirrors and rotation (as the
// tangent and handedness of rbl__billboardVertices)
static void rbl__frameAxes(bool rotated, bool flipU, bool flipV, float t[2], float v[2])
{
    if (!rotated) { t[0] = flipU? -1.0f : 1.0f; t[1] = 0.0f; v[0] = 0.0f; v[1] = flipV? 1.0f : -1.0f; }
    else { t[0] = 0.0f; t[1] = flipV? -1.0f : 1.0f; v[0] = flipU? -1.0f : 1.0f; v[1] = 0.0f; }
}

// Positions of the picture's edges (quad fractions 0 and 1, top-left origin) in clip rectangle c
// (zero = the whole quad): out = { x at 0, x at 1, y at 0, y at 1 }; an axis c covers whole is 0.5,
// so frames of equal trim are never clipped by rounding (lit_instanced.vs.glsl's rblFadeClipLocal)
static void rbl__fadeClipEdges(Rectangle c, float out[4])
{
    out[0] = out[1] = out[2] = out[3] = 0.5f;
    if (!((c.width > 0.0f) && (c.height > 0.0f))) return;
    if (!((c.x <= 0.0f) && (c.x + c.width >= 1.0f))) { float inv = 1.0f/c.width; out[0] = -c.x*inv; out[1] = (1.0f - c.x)*inv; }
    if (!((c.y <= 0.0f) && (c.y + c.height >= 1.0f))) { float inv = 1.0f/c.height; out[2] = -c.y*inv; out[3] = (1.0f - c.y)*inv; }
}

// The fade stream of a billboard (rbl__billboardOk passed): per corner (bottom-left, bottom-right,
// top-right, top-left) the second frame's texture coordinate, the weight, and its axes against the
// first frame's as material.glsl's rblFadeAxes reads them (swap + 2 negT + 4 negV); then each
// frame's position in its clip rectangle (material.glsl fragFadeClip)
static void rbl__fadeVertices(const RblBillboard *b, const RblFade *fade, int textureWidth, int textureHeight, float out[RBL__FADE_FLOATS])
{
    Rectangle src[2] = { b->source, fade->source };
    bool rotated[2] = { (b->flags & RBL_FRAME_ROTATED) != 0, (fade->flags & RBL_FRAME_ROTATED) != 0 };
    float t[2][2], v[2][2];
    for (int k = 0; k < 2; k++)
    {
        if ((src[k].x == 0.0f) && (src[k].y == 0.0f) && (src[k].width == 0.0f) && (src[k].height == 0.0f)) { src[k].width = (float)textureWidth; src[k].height = (float)textureHeight; }
        rbl__frameAxes(rotated[k], (b->size.x < 0.0f) != (src[k].width < 0.0f), (b->size.y < 0.0f) != (src[k].height < 0.0f), t[k], v[k]);
    }
    float x = t[1][0]*v[0][0] + t[1][1]*v[0][1];
    bool swap = (x != 0.0f);
    float dt = swap? x : (t[1][0]*t[0][0] + t[1][1]*t[0][1]);
    float dv = swap? (v[1][0]*t[0][0] + v[1][1]*t[0][1]) : (v[1][0]*v[0][0] + v[1][1]*v[0][1]);
    float code = (swap? 1.0f : 0.0f) + ((dt < 0.0f)? 2.0f : 0.0f) + ((dv < 0.0f)? 4.0f : 0.0f);
    // Texture coordinates as rbl__billboardVertices computes the first frame's (same corners, mirrors)
    const Rectangle f = src[1];
    bool flipU = (b->size.x < 0.0f) != (f.width < 0.0f), flipV = (b->size.y < 0.0f) != (f.height < 0.0f);
    float invW = 1.0f/(float)textureWidth, invH = 1.0f/(float)textureHeight;
    float fu0 = f.x*invW, fu1 = (f.x + fabsf(f.width))*invW, fv0 = f.y*invH, fv1 = (f.y + fabsf(f.height))*invH;
    static const float cs[4] = { 0.0f, 1.0f, 1.0f, 0.0f }, ct[4] = { 1.0f, 1.0f, 0.0f, 0.0f };
    float edges[2][4];
    rbl__fadeClipEdges(fade->clip[0], edges[0]);
    rbl__fadeClipEdges(fade->clip[1], edges[1]);
    for (int i = 0; i < 4; i++)
    {
        float sc = flipU? 1.0f - cs[i] : cs[i], tc = flipV? 1.0f - ct[i] : ct[i];
        float fu = rotated[1]? 1.0f - tc : sc, fv = rotated[1]? sc : tc;     // frame position (a rotated frame: sprite (s,t) at (1-t, s))
        float *o = out + i*RBL__FADE_VERTEX_FLOATS;
        o[0] = (fu > 0.5f)? fu1 : fu0;
        o[1] = (fv > 0.5f)? fv1 : fv0;
        o[2] = fade->weight;
        o[3] = code;
        // Clip rectangles are in the picture: a mirrored quad mirrors them with it
        int ps = ((b->size.x < 0.0f) != (cs[i] > 0.5f))? 1 : 0, pt = ((b->size.y < 0.0f) != (ct[i] > 0.5f))? 1 : 0;
        o[4] = edges[0][ps]; o[5] = edges[0][2 + pt];
        o[6] = edges[1][ps]; o[7] = edges[1][2 + pt];
    }
}

// ---- polygon frames: handles, lookup --------------------------------------------------------------
// A billboard's or instance's RBL_FRAME_POLYGON bits name one registered polygon (an atlas's frame).
// Flags from 2^24 up carry none: the instanced stage reads flags as a float, exact below 2^24 only.
#define RBL__POLYGON_SHIFT 4
#define RBL__POLYGON_HANDLES 0xFFFFFu

static inline unsigned int rbl__polygonHandle(unsigned int flags)
{
    return (flags < 0x1000000u)? (flags & (unsigned int)RBL_FRAME_POLYGON) >> RBL__POLYGON_SHIFT : 0u;
}

// The polygon of a handle, or NULL when no loaded atlas holds it (ranges sorted by first handle)
static const rbl__Polygon *rbl__polygonAt(unsigned int handle)
{
    int lo = 0, hi = rbl__state.polyRangeCount;
    while (lo < hi)
    {
        int mid = (lo + hi)/2;
        const rbl__PolyRange *r = &rbl__state.polyRanges[mid];
        if (r->first + (unsigned int)r->count <= handle) lo = mid + 1; else hi = mid;
    }
    if ((lo < rbl__state.polyRangeCount) && (rbl__state.polyRanges[lo].first <= handle)) return &rbl__state.polyRanges[lo].polygons[handle - rbl__state.polyRanges[lo].first];
    return NULL;
}

// A billboard's polygon: *out NULL for the quad; false when its bits name no loaded polygon
// The bits an atlas sets in a billboard's flags (the rest are the caller's)
#define RBL__FRAME_BITS ((unsigned int)RBL_FRAME_ROTATED | (unsigned int)RBL_FRAME_POLYGON)

static inline bool rbl__billboardPolygon(unsigned int flags, const rbl__Polygon **out)
{
    unsigned int h = rbl__polygonHandle(flags);
    *out = (h != 0u)? rbl__polygonAt(h) : NULL;
    return (h == 0u) || (*out != NULL);
}

#if !defined(RBL_NO_ATLAS)
// Whether handles [first, first + count) are all free and valid
static bool rbl__polygonRangeFree(unsigned int first, int count)
{
    if ((first == 0u) || ((unsigned int)count > RBL__POLYGON_HANDLES) || (first > RBL__POLYGON_HANDLES + 1u - (unsigned int)count)) return false;
    for (int i = 0; i < rbl__state.polyRangeCount; i++)
    {
        const rbl__PolyRange *r = &rbl__state.polyRanges[i];
        if ((first < r->first + (unsigned int)r->count) && (r->first < first + (unsigned int)count)) return false;
    }
    return true;
}

// Registers count polygons under consecutive handles: the first, or 0 when none are left or out of
// memory. New handles follow the last ones handed out, so a billboard kept past its atlas's unload is
// refused rather than drawn as another atlas's polygon (until 2^20 - 1 handles ran out: then reused)
static unsigned int rbl__polygonRegister(const rbl__Polygon *polygons, int count)
{
    unsigned int first = (rbl__state.polyNext == 0u)? 1u : rbl__state.polyNext;
    if (!rbl__polygonRangeFree(first, count))
    {
        first = 1u;
        for (int i = 0; (i <= rbl__state.polyRangeCount) && !rbl__polygonRangeFree(first, count); i++)
        {
            if (i == rbl__state.polyRangeCount) { first = 0u; break; }
            first = rbl__state.polyRanges[i].first + (unsigned int)rbl__state.polyRanges[i].count;
        }
        if ((first == 0u) || !rbl__polygonRangeFree(first, count)) return 0u;
    }
    if (rbl__state.polyRangeCount == rbl__state.polyRangeCapacity)
    {
        int cap = (rbl__state.polyRangeCapacity > 0)? 2*rbl__state.polyRangeCapacity : 8;
        rbl__PolyRange *r = (rbl__PolyRange *)RBL_REALLOC(rbl__state.polyRanges, (size_t)cap*sizeof(rbl__PolyRange));
        if (r == NULL) return 0u;
        rbl__state.polyRanges = r;
        rbl__state.polyRangeCapacity = cap;
    }
    int at = 0;
    while ((at < rbl__state.polyRangeCount) && (rbl__state.polyRanges[at].first < first)) at++;
    memmove(&rbl__state.polyRanges[at + 1], &rbl__state.polyRanges[at], (size_t)(rbl__state.polyRangeCount - at)*sizeof(rbl__PolyRange));
    rbl__state.polyRanges[at].first = first;
    rbl__state.polyRanges[at].count = count;
    rbl__state.polyRanges[at].polygons = polygons;
    rbl__state.polyRangeCount++;
    rbl__state.polyNext = first + (unsigned int)count;
    rbl__state.polyVersion++;
    return first;
}

static void rbl__polygonUnregister(unsigned int first)
{
    for (int i = 0; i < rbl__state.polyRangeCount; i++)
        if (rbl__state.polyRanges[i].first == first)
        {
            memmove(&rbl__state.polyRanges[i], &rbl__state.polyRanges[i + 1], (size_t)(rbl__state.polyRangeCount - i - 1)*sizeof(rbl__PolyRange));
            rbl__state.polyRangeCount--;
            rbl__state.polyVersion++;
            return;
        }
}
#endif

// The frame diagonal the quad's triangles meet on for these mirrors and rotation: 0 (a = b) or 1
// (a + b = 1); lit_instanced.vs.glsl's rblPolygonChoose is the twin
static inline int rbl__polygonDiagonal(bool flipU, bool flipV, bool rotated) { return ((flipU != flipV) != rotated)? 0 : 1; }

// The cut a billboard draws: flat, the file's triangles; rounded, those cut along its quad's diagonal
static inline int rbl__billboardCut(const RblBillboard *b)
{
    if (!(b->roundness > 0.0f)) return 2;
    return rbl__polygonDiagonal((b->size.x < 0.0f) != (b->source.width < 0.0f), (b->size.y < 0.0f) != (b->source.height < 0.0f), (b->flags & RBL_FRAME_ROTATED) != 0);
}

// Slots a billboard takes in a batch: 1 for the quad, one per slot of its polygon (0: nothing drawn)
static inline int rbl__slotCount(const rbl__Polygon *poly, const RblBillboard *b) { return (poly != NULL)? poly->slotCount[rbl__billboardCut(b)] : 1; }

static bool rbl__expandQuad(const RblCameraFrame *view, const rbl__Cast *cast, rbl__FrameCache *cache, int textureWidth, int textureHeight, const RblBillboard *b, const rbl__Polygon *poly, RblVertex *out, float centre[3]);

static inline bool rbl__expandBillboard(const RblCameraFrame *view, const rbl__Cast *cast, rbl__FrameCache *cache, int textureWidth, int textureHeight, const RblBillboard *b, RblVertex out[4])
{
    return rbl__expandQuad(view, cast, cache, textureWidth, textureHeight, b, NULL, out, NULL);
}

static bool rbl__billboardVertices(const RblCameraFrame *view, const rbl__Cast *cast, rbl__FrameCache *cache, int textureWidth, int textureHeight, const RblBillboard *b, RblVertex out[4])
{
    if (!rbl__billboardOk(b, textureWidth, textureHeight)) return false;
    return rbl__expandBillboard(view, cast, cache, textureWidth, textureHeight, b, out);
}

// A quad's parts once b is known good: its frame (rotated), footprint, pivot (an AXIS caster's tilt
// applied), texture corners, tangent, tint and roundness: what its vertices or its batch record hold
typedef struct rbl__QuadParts {
    Vector3 P, R, U, N, T;          // Pivot, rotated unit axes, the frame's normal (not R x U under a CAMERA_PLANE caller up), tangent (+U of the texture)
    float x0, x1, y0, y1;           // Footprint along R and U from the pivot
    float uv[4][2];                 // Texture coordinates at BL, BR, TR, TL
    float w;                        // Handedness (cross(N, T)*w = +V)
    float round;                    // Roundness clamped to 0..1
    bool flipU, flipV, rotated, cylinder;
    unsigned char col[4];           // Tint (zero = white)
    Rectangle src;                  // Source frame (zero = whole texture filled in)
    float invW, invH;               // 1/texture size
} rbl__QuadParts;

static void rbl__quadParts(const RblCameraFrame *view, const rbl__Cast *cast, rbl__FrameCache *cache, int textureWidth, int textureHeight, const RblBillboard *b, rbl__QuadParts *q)
{
    rbl__facingFrame(view, cast, b, cache);
    Vector3 R = cache->right, U = cache->up, N = cache->normal;

    // Rotate the frame around the normal (raylib rotates the corners; same result, fewer ops)
    if (b->rotation != 0.0f)
    {
        float s, c;
        rbl__sinCosDeg(b->rotation, &s, &c);
        Vector3 nr = cache->normalXRight, nu = cache->normalXUp;
        R = rbl__v3(R.x*c + nr.x*s, R.y*c + nr.y*s, R.z*c + nr.z*s);
        U = rbl__v3(U.x*c + nu.x*s, U.y*c + nu.y*s, U.z*c + nu.z*s);
    }

    // Footprint: |size| with the pivot measured from the bottom-left, whatever the flips. R and U are
    // unit; CAMERA_PLANE with a caller up scales the height by |up|, as raylib does.
    float ulen = cache->upLength;
    float sx = fabsf(b->size.x), sy = fabsf(b->size.y);
    float x0 = -b->origin.x, x1 = sx - b->origin.x;
    float y0 = -b->origin.y, y1 = sy*ulen - b->origin.y;
    Vector3 P = b->position;
    if ((cast != NULL) && (b->facing == RBL_FACING_AXIS))
    {
        // A tilted AXIS caster turns about a line across the quad at height h along the axis, not
        // the pivot line: its lowest edge (a sprite standing on the ground keeps its feet there,
        // whatever its pivot) under a low light, moving to mid-height as the light nears the axis
        // (within 30 degrees; smoothstep of |l.a| from cos 30 to 1): there the shadow, centred on
        // the quad, is the same whichever side the tilt leans to, so it does not jump as the light
        // passes over. Turning by T about r moves corner offset o to T o; about the line through a h,
        // to T o + h (a - T a), T a = the tilted up; h from the untilted (rotated) frame, where R.a =
        // sin and U.a = cos of the rotation
        Vector3 a = rbl__v3(0.0f, 1.0f, 0.0f), l;
        if (rbl__len2(b->axis) > 1e-24f) rbl__normalizeTo(b->axis, &a);
        Vector3 d = rbl__sub(a, cache->up);
        if ((rbl__len2(d) > 0.0f) &&
            rbl__normalizeTo(rbl__v3(cast->light.x - P.x*cast->light.w, cast->light.y - P.y*cast->light.w, cast->light.z - P.z*cast->light.w), &l))
        {
            float s = 0.0f, c = 1.0f;
            if (b->rotation != 0.0f) rbl__sinCosDeg(b->rotation, &s, &c);
            float e0 = s*x0 + c*y0, e1 = s*x1 + c*y0, e2 = s*x1 + c*y1, e3 = s*x0 + c*y1;
            float lo = fminf(fminf(e0, e1), fminf(e2, e3)), hi = fmaxf(fmaxf(e0, e1), fmaxf(e2, e3));
            float t = fminf(fmaxf((fabsf(rbl__dot(l, a)) - 0.8660254f)*(1.0f/(1.0f - 0.8660254f)), 0.0f), 1.0f);
            float h = lo + 0.5f*(hi - lo)*(t*t*(3.0f - 2.0f*t));
            P = rbl__v3(P.x + d.x*h, P.y + d.y*h, P.z + d.z*h);
        }
    }
    // Source frame (zero = whole texture); flips mirror inside it. As raylib's DrawTexturePro, a
    // negative extent flips and the rectangle still starts at (x, y).
    Rectangle src = b->source;
    if ((src.x == 0.0f) && (src.y == 0.0f) && (src.width == 0.0f) && (src.height == 0.0f))
    {
        src.width = (float)textureWidth; src.height = (float)textureHeight;
    }
    bool flipU = (b->size.x < 0.0f) != (src.width < 0.0f);
    bool flipV = (b->size.y < 0.0f) != (src.height < 0.0f);
    bool rotated = (b->flags & RBL_FRAME_ROTATED) != 0;
    float invW = 1.0f/(float)textureWidth, invH = 1.0f/(float)textureHeight;
    float fu0 = src.x*invW, fu1 = (src.x + fabsf(src.width))*invW;     // frame edges in texture space
    float fv0 = src.y*invH, fv1 = (src.y + fabsf(src.height))*invH;
    // Corners in sprite space (s right, t down): BL (0,1), BR (1,1), TR (1,0), TL (0,0); a mirror
    // swaps the ends of its sprite axis. A rotated frame holds the sprite turned 90 degrees
    // clockwise, sprite (s,t) at frame (1-t, s): u then runs along sprite t and v along sprite s.
    float uv[4][2];
    if (!rotated)
    {
        float sl = flipU? fu1 : fu0, sr = flipU? fu0 : fu1;      // u at sprite left / right
        float tt = flipV? fv1 : fv0, tb = flipV? fv0 : fv1;      // v at sprite top / bottom
        uv[0][0] = sl; uv[0][1] = tb; uv[1][0] = sr; uv[1][1] = tb;
        uv[2][0] = sr; uv[2][1] = tt; uv[3][0] = sl; uv[3][1] = tt;
    }
    else
    {
        float tt = flipV? fu0 : fu1, tb = flipV? fu1 : fu0;      // u at sprite top / bottom
        float sl = flipU? fv1 : fv0, sr = flipU? fv0 : fv1;      // v at sprite left / right
        uv[0][0] = tb; uv[0][1] = sl; uv[1][0] = tb; uv[1][1] = sr;
        uv[2][0] = tt; uv[2][1] = sr; uv[3][0] = tt; uv[3][1] = sl;
    }

    // Tangent (+U) and handedness. In the right-handed frame (R x U = N), +V = -U unflipped, so
    // cross(N, T)*w = +V needs w = -1; each mirror flips w, a rotated frame keeps it.
    Vector3 T;
    if (!rotated) T = flipU? rbl__neg(R) : R;
    else T = flipV? rbl__neg(U) : U;
    float w = (flipU != flipV)? 1.0f : -1.0f;

    unsigned char col[4] = { b->tint.r, b->tint.g, b->tint.b, b->tint.a };
    if ((col[0] | col[1] | col[2] | col[3]) == 0) { col[0] = col[1] = col[2] = col[3] = 255; }

    float round = b->roundness;
    if (round < 0.0f) round = 0.0f;
    if (round > 1.0f) round = 1.0f;
    bool cylinder = (b->flags & RBL_ROUND_CYLINDER) != 0;
    q->P = P; q->R = R; q->U = U; q->N = N; q->T = T;
    q->x0 = x0; q->x1 = x1; q->y0 = y0; q->y1 = y1;
    memcpy(q->uv, uv, sizeof(uv));
    q->w = w; q->round = round; q->cylinder = cylinder;
    q->flipU = flipU; q->flipV = flipV; q->rotated = rotated;
    memcpy(q->col, col, 4);
    q->src = src; q->invW = invW; q->invH = invH;
}

// rbl__billboardVertices once b is known good: the quad's four corners, or with poly its slots (4
// vertices each) at the quad's own attributes: position, texture coordinate and (affine over each of
// the quad's two triangles, as the rasteriser interpolates them) normal and tangent, and the quad's
// centre (the sort key of each slot)
static bool rbl__expandQuad(const RblCameraFrame *view, const rbl__Cast *cast, rbl__FrameCache *cache, int textureWidth, int textureHeight, const RblBillboard *b, const rbl__Polygon *poly, RblVertex *out, float centre[3])
{
    rbl__QuadParts parts;
    rbl__quadParts(view, cast, cache, textureWidth, textureHeight, b, &parts);
    const Vector3 P = parts.P, R = parts.R, U = parts.U, N = parts.N, T = parts.T;
    const float x0 = parts.x0, x1 = parts.x1, y0 = parts.y0, y1 = parts.y1, w = parts.w, round = parts.round;
    const bool flipU = parts.flipU, flipV = parts.flipV, rotated = parts.rotated, cylinder = parts.cylinder;
    const Rectangle src = parts.src;
    const float invW = parts.invW, invH = parts.invH;
    Vector3 p[4];
    p[0] = rbl__v3(P.x + R.x*x0 + U.x*y0, P.y + R.y*x0 + U.y*y0, P.z + R.z*x0 + U.z*y0);
    p[1] = rbl__v3(P.x + R.x*x1 + U.x*y0, P.y + R.y*x1 + U.y*y0, P.z + R.z*x1 + U.z*y0);
    p[2] = rbl__v3(P.x + R.x*x1 + U.x*y1, P.y + R.y*x1 + U.y*y1, P.z + R.z*x1 + U.z*y1);
    p[3] = rbl__v3(P.x + R.x*x0 + U.x*y1, P.y + R.y*x0 + U.y*y1, P.z + R.z*x0 + U.z*y1);
    // No corner can overflow: rbl__billboardOk bounds the pivot, size and origin below 2^60 and
    // CAMERA_PLANE's up below 2^30, R and U are unit and an AXIS caster's tilt moves the pivot by
    // less than twice the footprint, so every sum stays below 2^93 (no check per corner here)

    static const float dxs[4] = { -1.0f, 1.0f, 1.0f, -1.0f }, dys[4] = { -1.0f, -1.0f, 1.0f, 1.0f };

    RblVertex corners[4];
    RblVertex *q = (poly != NULL)? corners : out;
    for (int i = 0; i < 4; i++)
    {
        RblVertex *v = &q[i];
        v->position[0] = p[i].x; v->position[1] = p[i].y; v->position[2] = p[i].z;
        v->texcoord[0] = parts.uv[i][0]; v->texcoord[1] = parts.uv[i][1];
        Vector3 n = N, tg = T;
        if (round > 0.0f)
        {
            // Corner normals lean outward from the quad centre: 45 degrees for a cylinder, 54.7 for a
            // sphere at full roundness; their interpolated mean stays the flat normal, never zero.
            float dx = dxs[i]*round, dy = cylinder? 0.0f : dys[i]*round;
            rbl__normalizeTo(rbl__v3(N.x + R.x*dx + U.x*dy, N.y + R.y*dx + U.y*dy, N.z + R.z*dx + U.z*dy), &n);
            if (!rbl__perpendicular(T, n, &tg)) tg = T;
        }
        v->normal[0] = n.x; v->normal[1] = n.y; v->normal[2] = n.z;
        v->tangent[0] = tg.x; v->tangent[1] = tg.y; v->tangent[2] = tg.z; v->tangent[3] = w;
        memcpy(v->color, parts.col, 4);
    }
    if (poly != NULL)
    {
        // A polygon vertex at frame fractions (a, b) of the source lies at sprite (s, t) (as the
        // corners: a mirror swaps an axis's ends, a rotated frame holds sprite (s,t) at (1-t, s)),
        // quad fraction (s, 1 - t) from the bottom-left. A mirror turns the triangles over: each
        // slot is then walked the other way round, (A, D, C, B), a lone triangle (A, C, B, B), so
        // they face as the quad does.
        static const int back[2][4] = { { 0, 3, 2, 1 }, { 0, 2, 1, 1 } };
        const bool reverse = flipU != flipV;
        const int diagonal = (round > 0.0f)? rbl__polygonDiagonal(flipU, flipV, rotated) : 2;     // rbl__billboardCut
        const float su = fabsf(src.width), sv = fabsf(src.height);
        for (int e = 0; e < 3; e++) centre[e] = 0.25f*(q[0].position[e] + q[1].position[e] + q[2].position[e] + q[3].position[e]);
        for (int k = 0; k < poly->slotCount[diagonal]; k++)
            for (int c = 0; c < 4; c++)
            {
                const unsigned int *slot = poly->slots[diagonal] + 4*k;
                const Vector2 f = poly->frac[slot[reverse? back[slot[2] == slot[3]][c] : c]];
                float s = rotated? f.y : f.x, t = rotated? 1.0f - f.x : f.y;
                if (flipU) s = 1.0f - s;
                if (flipV) t = 1.0f - t;
                const float up = 1.0f - t, x = x0*(1.0f - s) + x1*s, y = y0*(1.0f - up) + y1*up;
                RblVertex *v = &out[4*k + c];
                v->position[0] = P.x + R.x*x + U.x*y; v->position[1] = P.y + R.y*x + U.y*y; v->position[2] = P.z + R.z*x + U.z*y;
                v->texcoord[0] = (src.x + f.x*su)*invW; v->texcoord[1] = (src.y + f.y*sv)*invH;
                // Which of the quad's triangles (0,1,2) or (0,2,3) holds it, and its weights there
                int i1 = (s >= up)? 1 : 2, i2 = (s >= up)? 2 : 3;
                float w0 = (s >= up)? 1.0f - s : 1.0f - up, w1 = (s >= up)? s - up : s, w2 = (s >= up)? up : up - s;
                for (int e = 0; e < 3; e++)
                {
                    v->normal[e] = (round > 0.0f)? q[0].normal[e]*w0 + q[i1].normal[e]*w1 + q[i2].normal[e]*w2 : q[0].normal[e];
                    v->tangent[e] = (round > 0.0f)? q[0].tangent[e]*w0 + q[i1].tangent[e]*w1 + q[i2].tangent[e]*w2 : q[0].tangent[e];
                }
                v->tangent[3] = w;
                memcpy(v->color, parts.col, 4);
            }
    }
    return true;
}

bool RblBillboardVertices(const RblCameraFrame *view, int textureWidth, int textureHeight, const RblBillboard *b, RblVertex out[4])
{
    const char *bad = NULL;
    if ((view == NULL) || (b == NULL) || (out == NULL)) bad = "NULL view, billboard or out";
    else if (!rbl__bounded3(view->eye) || !rbl__unit3(view->right) || !rbl__unit3(view->up) || !rbl__unit3(view->back)) bad = "view is not a camera frame (NaN/Inf, huge eye or non-unit axes)";
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblBillboardVertices: %s", bad); return false; }
    rbl__FrameCache cache;
    cache.facing = -1;
    if (!rbl__billboardVertices(view, NULL, &cache, textureWidth, textureHeight, b, out))
    {
        TraceLog(LOG_WARNING, "RBL: RblBillboardVertices: billboard skipped (NaN/Inf or huge input, bad facing or texture size %ix%i)", textureWidth, textureHeight);
        return false;
    }
    return true;
}

int RblBillboardQuads(const RblCameraFrame *view, int textureWidth, int textureHeight, const RblBillboard *b, RblVertex *out, int capacity)
{
    const char *bad = NULL;
    const rbl__Polygon *poly = NULL;
    if ((view == NULL) || (b == NULL) || (capacity < 0)) bad = "NULL view or billboard, or negative capacity";
    else if (!rbl__bounded3(view->eye) || !rbl__unit3(view->right) || !rbl__unit3(view->up) || !rbl__unit3(view->back)) bad = "view is not a camera frame (NaN/Inf, huge eye or non-unit axes)";
    else if (!rbl__billboardOk(b, textureWidth, textureHeight)) bad = "billboard skipped (NaN/Inf or huge input, bad facing or texture size)";
    else if (!rbl__billboardPolygon(b->flags, &poly)) bad = "its RBL_FRAME_POLYGON bits name no loaded atlas's polygon (unloaded atlas?)";
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblBillboardQuads: %s", bad); return -1; }
    const int quads = rbl__slotCount(poly, b);
    if ((out == NULL) || (capacity < quads)) return quads;
    rbl__FrameCache cache;
    cache.facing = -1;
    float centre[3];
    rbl__expandQuad(view, NULL, &cache, textureWidth, textureHeight, b, poly, out, centre);
    return quads;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: batched and immediate paths   >>batch
//----------------------------------------------------------------------------------
// Map slots of a caster material: DrawMesh reads MAX_MATERIAL_MAPS of them (raylib's config.h, 12 by
// default and not visible here), so the array is generously larger than any build's
#define RBL__CASTER_MAPS 32
// What a draw feeds the vertex stage: billboard quads, instances, a Model's mesh, or a GPU-skinned
// mesh with its Model's bone matrices (a skinned program needs the last; casters skin for it)
enum { RBL__PATH_BILLBOARD = 0, RBL__PATH_INSTANCED, RBL__PATH_MESH, RBL__PATH_SKINNED };
// Inside a shadow pass every billboard path draws casters, with the same calls and materials as the
// colour pass; per-material values go with each draw (defined with the lit programs)
static void rbl__shadowPassView(RblCameraFrame *view);
static bool rbl__prepareDraw(Material *material, MaterialMap casterMaps[RBL__CASTER_MAPS], int path, bool fade, bool record, const char *fn, rbl__Program **program);
static const char *rbl__materialProblem(const Material *material, int path, rbl__Program **program);
static void rbl__applyMaterialValues(rbl__Program *p, const Material *material);
static bool rbl__programAlive(const rbl__Program *p);
static void rbl__forgetProgram(rbl__Program *p);
static void rbl__removeProgram(rbl__Program *p);
static void rbl__noteDroppedShadow(void);
static void rbl__markDrawn(const rbl__Program *p);
static void rbl__releaseCapture(void);

static void rbl__loadBatchGpu(rbl__BatchState *batch)
{
    int quads = batch->capacity;
    batch->eboId = 0;               // stays 0 if the index allocation fails (never the old, smaller buffer)
    batch->vaoId = rlLoadVertexArray();
    rlEnableVertexArray(batch->vaoId);
    batch->vboId = rlLoadVertexBuffer(NULL, quads*4*(int)sizeof(RblVertex), true);

    int chunkQuads = (quads < RBL__QUADS_PER_CHUNK)? quads : RBL__QUADS_PER_CHUNK;
    unsigned short *indices = (unsigned short *)RBL_MALLOC((size_t)chunkQuads*6*sizeof(unsigned short));
    if (indices != NULL)
    {
        for (int q = 0; q < chunkQuads; q++)
        {
            unsigned short b = (unsigned short)(q*4);
            unsigned short *ix = indices + q*6;
            ix[0] = b; ix[1] = (unsigned short)(b + 1); ix[2] = (unsigned short)(b + 2);
            ix[3] = b; ix[4] = (unsigned short)(b + 2); ix[5] = (unsigned short)(b + 3);
        }
        batch->eboId = rlLoadVertexBufferElement(indices, chunkQuads*6*(int)sizeof(unsigned short), false);
        RBL_FREE(indices);
    }
    rlDisableVertexArray();
    batch->gpuCapacity = quads;
}

// ---- records written into the mapped GPU buffer ----
#define RBL__GL_ARRAY_BUFFER 0x8892
#define RBL__GL_MAP_READ_BIT 0x0001
#define RBL__GL_MAP_WRITE_BIT 0x0002
#define RBL__GL_MAP_INVALIDATE_BUFFER_BIT 0x0008
// Batches that keep their records on the CPU after one had to read mapped records back: a scene that
// mixes a polygon or a fade into its batch every frame stops paying the read-back
#define RBL__MAP_REST 64
typedef void *(RBL__GLAPI *rbl__GlMapBufferRange)(unsigned int target, ptrdiff_t offset, ptrdiff_t length, unsigned int access);
typedef unsigned char (RBL__GLAPI *rbl__GlUnmapBuffer)(unsigned int target);

// Whether the context maps buffers (GL 3, ES 3 through raylib's loader; WebGL has no mapping)
static bool rbl__canMap(void)
{
#if defined(RBL_NO_MAPPED_BATCH) || defined(__EMSCRIPTEN__)
    return false;
#else
    if (!rbl__state.mapLooked && (rbl__glsl() >= 300) && (rlGetTextureIdDefault() != 0))
    {
        rbl__state.glMapBufferRange = rlGetProcAddress("glMapBufferRange");
        rbl__state.glUnmapBuffer = rlGetProcAddress("glUnmapBuffer");
        rbl__state.mapLooked = true;
    }
    return (rbl__state.glMapBufferRange != NULL) && (rbl__state.glUnmapBuffer != NULL);
#endif
}

// bytes of vertex buffer vbo from its start as a pointer (read: for reading; else written whole,
// the old contents dropped), or NULL; the buffer is left unbound
static void *rbl__mapBuffer(unsigned int vbo, size_t bytes, bool read)
{
    rbl__GlMapBufferRange map;
    memcpy(&map, &rbl__state.glMapBufferRange, sizeof(map));      // ISO C: no cast between object and function pointers
    rlEnableVertexBuffer(vbo);
    void *p = map(RBL__GL_ARRAY_BUFFER, 0, (ptrdiff_t)bytes, read? RBL__GL_MAP_READ_BIT : (RBL__GL_MAP_WRITE_BIT | RBL__GL_MAP_INVALIDATE_BUFFER_BIT));
    rlDisableVertexBuffer();
    return p;
}

// Ends a mapping of vertex buffer vbo; false when the system lost its contents meanwhile
static bool rbl__unmapBuffer(unsigned int vbo)
{
    rbl__GlUnmapBuffer unmap;
    memcpy(&unmap, &rbl__state.glUnmapBuffer, sizeof(unmap));
    rlEnableVertexBuffer(vbo);
    bool kept = (unmap(RBL__GL_ARRAY_BUFFER) != 0);
    rlDisableVertexBuffer();
    return kept;
}

// From the first record on, the adds write records into the GPU buffer (where it maps)
static void rbl__mapRecords(rbl__BatchState *batch)
{
    batch->mapped = (rbl__BatchRecord *)rbl__mapBuffer(batch->vboId, (size_t)batch->gpuCapacity*sizeof(rbl__BatchRecord), false);
    batch->onGpu = (batch->mapped != NULL);
}

// Records that are only in the GPU buffer, read back into the CPU array before a step reads them
// (turning to vertices, sorting, growing); a batch in progress stops mapping for a while. False when
// the system lost them: the billboards added so far are dropped (logged)
static bool rbl__recordsToCpu(rbl__BatchState *batch)
{
    if (!batch->onGpu) return true;
    bool kept = (batch->mapped == NULL) || rbl__unmapBuffer(batch->vboId);
    batch->mapped = NULL;
    batch->onGpu = false;
    if (batch->begun) { batch->mapOk = false; batch->mapRest = RBL__MAP_REST; }
    if (kept && (batch->count > 0))
    {
        const size_t bytes = (size_t)batch->count*sizeof(rbl__BatchRecord);
        const void *p = rbl__mapBuffer(batch->vboId, bytes, true);
        if (p != NULL) memcpy(batch->vertices, p, bytes);
        kept = (p != NULL) && rbl__unmapBuffer(batch->vboId);
    }
    if (!kept)
    {
        TraceLog(LOG_WARNING, "RBL: batch: the GPU lost the records of %i billboards (its buffer was unmapped by the system); they are not drawn", batch->count);
        batch->count = 0; batch->runCount = 0; batch->extraSlots = 0;
    }
    return kept;
}

static void rbl__unloadBatchGpu(rbl__BatchState *batch)
{
    if ((batch->mapped != NULL) && rbl__glUsable()) rbl__unmapBuffer(batch->vboId);
    batch->mapped = NULL;
    batch->onGpu = false;
    if (!rbl__glUsable()) batch->vaoId = batch->vboId = batch->eboId = batch->fadeVboId = batch->idVboId = batch->recordVaoId = 0;      // gone with the context
    if (batch->vaoId != 0) rlUnloadVertexArray(batch->vaoId);
    if (batch->recordVaoId != 0) rlUnloadVertexArray(batch->recordVaoId);
    if (batch->vboId != 0) rlUnloadVertexBuffer(batch->vboId);
    if (batch->eboId != 0) rlUnloadVertexBuffer(batch->eboId);
    if (batch->fadeVboId != 0) rlUnloadVertexBuffer(batch->fadeVboId);
    if (batch->idVboId != 0) rlUnloadVertexBuffer(batch->idVboId);
    batch->vaoId = batch->vboId = batch->eboId = batch->fadeVboId = batch->idVboId = batch->recordVaoId = 0;
    batch->gpuCapacity = batch->fadeGpuCapacity = batch->idGpuCapacity = 0;
}

// The caster identity stream: per vertex the identity's high and low bytes (normalised) and two zero bytes
#define RBL__ID_BYTES 16

// MurmurHash3's 32-bit finaliser: every input bit reaches every output bit
static unsigned int rbl__mix32(unsigned int h)
{
    h ^= h >> 16; h = (h*0x85ebca6bu) & 0xffffffffu;
    h ^= h >> 13; h = (h*0xc2b2ae35u) & 0xffffffffu;
    return h ^ (h >> 16);
}

// A billboard's caster identity: 16 bits mixed from the float bits of its pivot, size and origin
// (the pivot is the one point every facing, tilt and light-facing turn keeps; size and origin tell
// apart cards sharing a pivot, a sprite standing on a tile's centre; the same bits give the same
// identity in any pass, order or path), never 0, which marks Models. lit_instanced.vs.glsl's
// rblCasterIdOf is the twin.
static unsigned int rbl__casterId(Vector3 pivot, Vector2 size, Vector2 origin)
{
    const float f[7] = { pivot.x, pivot.y, pivot.z, size.x, size.y, origin.x, origin.y };
    unsigned int h = 0u;
    for (int i = 0; i < 7; i++)
    {
        unsigned int b;
        memcpy(&b, &f[i], 4);
        h = rbl__mix32(h ^ b);
    }
    h = (h ^ (h >> 16)) & 0xffffu;
    return (h == 0u)? 1u : h;
}

static bool rbl__batchAdd(rbl__BatchState *batch, const Material *material, const RblBillboard *billboard, const RblFade *fade, const char *fn);

// The pass in progress: the shadow map's or G-buffer's id, 0 for a colour pass. A batch collects for
// one pass (its frame and programs are that pass's)
static inline unsigned int rbl__passNow(void)
{
    if (rbl__state.shadowPass != NULL) return rbl__state.shadowPass->id;
    if (rbl__state.gbufferPass != NULL) return rbl__state.gbufferPass->id;
    return 0;
}

// The state of a loaded batch, or NULL (never dereferences a stale copy's pointer)
static inline rbl__BatchState *rbl__batchState(const RblBatch *batch)
{
    return ((batch != NULL) && rbl__isLive(batch->id, batch->state))? batch->state : NULL;
}

static void rbl__freeBatchState(rbl__BatchState *b)
{
    rbl__unloadBatchGpu(b);
    RBL_FREE(b->vertices);
    RBL_FREE(b->sorted);
    RBL_FREE(b->keys);
    RBL_FREE(b->runs);
    RBL_FREE(b->fade);
    RBL_FREE(b->fadeSorted);
    RBL_FREE(b->ids);
    RBL_FREE(b->idsSorted);
    RBL_FREE(b->centres);
    RBL_FREE(b);
}

RblBatch RblLoadBatch(int capacity)
{
    RblBatch batch;
    memset(&batch, 0, sizeof(batch));
    if ((capacity < 0) || (capacity > RBL_MAX_BATCH_BILLBOARDS)) { TraceLog(LOG_WARNING, "RBL: RblLoadBatch: capacity %i outside 0..%i", capacity, RBL_MAX_BATCH_BILLBOARDS); return batch; }
    if (capacity == 0) capacity = RBL_BATCH_DEFAULT_CAPACITY;
    rbl__BatchState *b = (rbl__BatchState *)RBL_CALLOC(1, sizeof(rbl__BatchState));
    if (b != NULL)
    {
        b->vertices = (RblVertex *)RBL_MALLOC((size_t)capacity*4*sizeof(RblVertex));
        b->runCapacity = 16;
        b->runs = (rbl__BatchRun *)RBL_MALLOC((size_t)b->runCapacity*sizeof(rbl__BatchRun));
    }
    if ((b == NULL) || (b->vertices == NULL) || (b->runs == NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadBatch: out of memory for %i billboards", capacity);
        if (b != NULL) { RBL_FREE(b->vertices); RBL_FREE(b->runs); RBL_FREE(b); }
        return batch;
    }
    b->capacity = capacity;
    rbl__loadBatchGpu(b);
    unsigned int id = ((b->vaoId != 0) && (b->vboId != 0) && (b->eboId != 0))? rbl__liveAdd(b) : 0;
    if (id == 0)
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadBatch: GPU buffers could not be created (no GL context?)");
        rbl__freeBatchState(b);
        return batch;
    }
    batch.capacity = capacity;
    batch.state = b;
    batch.id = id;
    return batch;
}

bool RblIsBatchValid(RblBatch batch)
{
    return rbl__batchState(&batch) != NULL;
}

void RblUnloadBatch(RblBatch *batch)
{
    if (!rbl__unloadable(batch, (batch != NULL)? batch->id : 0, (batch != NULL)? batch->state : NULL, "RblUnloadBatch", "batch")) { if (batch != NULL) memset(batch, 0, sizeof(*batch)); return; }
    rbl__liveRemove(batch->id);
    rbl__freeBatchState(batch->state);
    memset(batch, 0, sizeof(*batch));
    if (batch != &rbl__state.immediate) rbl__tidyAfterClose();
}

// Culling planes of the transform the batch will draw with (rlgl's projection x modelview, a point
// p inside where every n.p + d >= 0; clip-space planes w +- x, w +- y, w +- z). A colour or G-buffer
// pass culls only where rlgl's modelview is the camera's view (inside BeginMode3D(camera) with no
// transform of the caller's pushed: else nothing is culled, never wrongly); a shadow pass by its
// light's four sides (the header set its matrices; casters before or beyond its depth range are
// kept). Returns the plane count (0 = no culling).
static int rbl__cullPlanes(const RblCameraFrame *view, bool shadowPass, float planes[6][4])
{
    Matrix mv = rlGetMatrixModelview(), pr = rlGetMatrixProjection();
    float a[16], b[16], m[16];
    rbl__matToArray(mv, a);
    rbl__matToArray(pr, b);
    if (!shadowPass)
    {
        // Rows of the view: right, up, back and their offsets -axis.eye (raymath's MatrixLookAt)
        const Vector3 axes[3] = { view->right, view->up, view->back };
        const float tol = 1e-4f, tolT = 1e-4f*(1.0f + fabsf(view->eye.x) + fabsf(view->eye.y) + fabsf(view->eye.z));
        for (int r = 0; r < 3; r++)
        {
            const float row[4] = { a[r], a[4 + r], a[8 + r], a[12 + r] };
            if (!((fabsf(row[0] - axes[r].x) <= tol) && (fabsf(row[1] - axes[r].y) <= tol) && (fabsf(row[2] - axes[r].z) <= tol) &&
                  (fabsf(row[3] + rbl__dot(axes[r], view->eye)) <= tolT))) return 0;
        }
        if (!((a[3] == 0.0f) && (a[7] == 0.0f) && (a[11] == 0.0f) && (a[15] == 1.0f))) return 0;
    }
    // m = modelview then projection (raylib's MatrixMultiply(mv, pr)), column-major as GL reads it
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            m[c*4 + r] = a[c*4 + 0]*b[0*4 + r] + a[c*4 + 1]*b[1*4 + r] + a[c*4 + 2]*b[2*4 + r] + a[c*4 + 3]*b[3*4 + r];
    int count = shadowPass? 4 : 6;
    for (int k = 0; k < count; k++)
    {
        int row = k/2;
        float sg = (k & 1)? -1.0f : 1.0f;       // w + row, w - row
        float p[4] = { m[3] + sg*m[row], m[7] + sg*m[4 + row], m[11] + sg*m[8 + row], m[15] + sg*m[12 + row] };
        float len = sqrtf(p[0]*p[0] + p[1]*p[1] + p[2]*p[2]);
        if (!rbl__finite(len) || !(len > 0.0f) || !rbl__finite(p[3])) return 0;
        for (int i = 0; i < 4; i++) planes[k][i] = p[i]/len;
    }
    return count;
}

// Whether the sphere about c of squared radius r2 lies wholly outside one of the eight planes (by
// component, rbl__BatchState.cull): every plane, no early exit. The scalar one is the reference of the
// four-lane one, and runs where there is none; both sum in the same order
static inline bool rbl__outsidePlanesScalar(const float cull[4][8], Vector3 c, float r2)
{
    int out = 0;
    for (int k = 0; k < 8; k++)
    {
        float d = cull[0][k]*c.x + cull[1][k]*c.y + cull[2][k]*c.z + cull[3][k];
        out |= (d < 0.0f) & (d*d > r2);
    }
    return out != 0;
}

RBL__FORCE_INLINE bool rbl__outsidePlanes(const float cull[4][8], Vector3 c, float r2)
{
#if defined(RBL__SSE2)
    const __m128 x = _mm_set1_ps(c.x), y = _mm_set1_ps(c.y), z = _mm_set1_ps(c.z), r = _mm_set1_ps(r2), zero = _mm_setzero_ps();
    __m128 out = zero;
    for (int h = 0; h < 8; h += 4)
    {
        __m128 d = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&cull[0][h]), x), _mm_mul_ps(_mm_loadu_ps(&cull[1][h]), y)),
                                         _mm_mul_ps(_mm_loadu_ps(&cull[2][h]), z)), _mm_loadu_ps(&cull[3][h]));
        out = _mm_or_ps(out, _mm_and_ps(_mm_cmplt_ps(d, zero), _mm_cmpgt_ps(_mm_mul_ps(d, d), r)));
    }
    return _mm_movemask_ps(out) != 0;
#else
    return rbl__outsidePlanesScalar(cull, c, r2);
#endif
}

static int rbl__backMode(const RblCameraFrame *view, int facing, Vector3 up, Vector3 axis, Vector3 *n);

// The batch's key for b (checked by rbl__billboardOk) before culling and storing it: what its facing,
// up and axis give, made again only when they change
RBL__FORCE_INLINE void rbl__facingKey(rbl__BatchState *batch, const RblBillboard *b)
{
    unsigned int w[7];
    memcpy(w, &b->facing, sizeof(w));
    const unsigned int *k = batch->keyWords;
    if (batch->keyValid && (((w[0] ^ k[0]) | (w[1] ^ k[1]) | (w[2] ^ k[2]) | (w[3] ^ k[3]) | (w[4] ^ k[4]) | (w[5] ^ k[5]) | (w[6] ^ k[6])) == 0u)) return;
    memcpy(batch->keyWords, w, sizeof(w));
    batch->keyValid = true;
    const bool plane = (b->facing == RBL_FACING_CAMERA_PLANE);
    const float l2 = rbl__len2(b->up);
    batch->keyHeightScale = (plane && (l2 > 0.0f))? sqrtf(l2) : 1.0f;
    batch->backMode = rbl__backMode(&batch->view, b->facing, plane? b->up : rbl__tame(b->up), plane? b->axis : rbl__tame(b->axis), &batch->backNormal);
}

// Whether billboard b (after rbl__facingKey) lies wholly outside one culling plane: its
// corners lie within the sphere about the pivot through the farthest footprint corner (rotation
// turns the footprint about the pivot; CAMERA_PLANE's caller up scales its height; a shadow pass's
// AXIS tilt moves it by at most twice that, so its sphere is three times as large)
RBL__FORCE_INLINE bool rbl__culled(const rbl__BatchState *batch, const RblBillboard *b)
{
    float sx = fabsf(b->size.x), sy = fabsf(b->size.y)*batch->keyHeightScale;
    float ax = fabsf(b->origin.x), bx = fabsf(sx - b->origin.x), ay = fabsf(b->origin.y), by = fabsf(sy - b->origin.y);
    float ex = (ax > bx)? ax : bx, ey = (ay > by)? ay : by;
    float r2 = (ex*ex + ey*ey)*(((batch->planeCount == 4) && (b->facing == RBL_FACING_AXIS))? 9.0f : 1.0f);
    r2 *= 1.0f + 1e-5f;        // rounding of the corners' own sums
    return rbl__outsidePlanes(batch->cull, b->position, r2);
}

// Order matters only where colour blends: shadow and G-buffer passes draw in submission order
static int rbl__passSort(int sort)
{
    return ((rbl__state.shadowPass != NULL) || (rbl__state.gbufferPass != NULL))? RBL_SORT_NONE : sort;
}

bool RblBeginBatch(RblBatch *pub, Camera3D camera)
{
    rbl__BatchState *batch = rbl__batchState(pub);
    if (batch == NULL) { TraceLog(LOG_WARNING, "RBL: RblBeginBatch: batch not loaded"); return false; }
    if (batch->begun && (batch->count > 0))
    {
        TraceLog(LOG_WARNING, "RBL: RblBeginBatch: %i billboards added since the last RblBeginBatch are not drawn yet (call RblEndBatch first)", batch->count);
        return false;
    }
    if (!rbl__cameraOk(camera)) { TraceLog(LOG_WARNING, "RBL: RblBeginBatch: camera with NaN/Inf fields"); return false; }
    batch->view = rbl__cameraFrame(camera);
    float planes[6][4];
    batch->planeCount = pub->noCull? 0 : rbl__cullPlanes(&batch->view, rbl__state.shadowPass != NULL, planes);
    for (int k = 0; k < 8; k++)
        for (int e = 0; e < 4; e++) batch->cull[e][k] = (k < batch->planeCount)? planes[k][e] : ((e == 3)? 1.0f : 0.0f);
    if (rbl__state.shadowPass != NULL) rbl__shadowPassView(&batch->view);
    batch->orthographic = (camera.projection == CAMERA_ORTHOGRAPHIC);
    batch->backFacing = false;
    batch->keyValid = false;
    batch->frame.facing = -1;      // the frame depends on the view
    batch->fading = false;
    batch->identified = false;
    batch->polygonal = false;
    batch->extraSlots = 0;
    batch->count = 0;
    batch->runCount = 0;
    batch->skipped = 0;
    batch->culled = 0;
    batch->records = false;
    if (batch->mapped != NULL) rbl__unmapBuffer(batch->vboId);   // (a first record that was never counted)
    batch->mapped = NULL;
    batch->onGpu = false;
    batch->mapOk = false;
    if (batch->mapRest > 0) batch->mapRest--;
    else batch->mapOk = !batch->vertexOnly && (rbl__passSort(pub->sort) == RBL_SORT_NONE) && (batch->vboId != 0) && (batch->capacity <= batch->gpuCapacity) && rbl__canMap();
    batch->begun = true;
    batch->pass = rbl__passNow();
    pub->count = 0; pub->skipped = 0; pub->culled = 0;
    return true;
}

// Whether material b continues a's run: the same shader, the same maps array (its contents are read
// when the run draws) and the same params, the per-material values the run draws with (a copy of a
// Material with another alpha cutoff is another material, as for raylib's DrawMesh)
static inline bool rbl__sameMaterial(const Material *a, const Material *b)
{
    unsigned int pa[4], pb[4];
    memcpy(pa, a->params, sizeof(pa));
    memcpy(pb, b->params, sizeof(pb));
    return (a->shader.id == b->shader.id) && (a->shader.locs == b->shader.locs) && (a->maps == b->maps) && (a->maps != NULL) &&
           (((pa[0] ^ pb[0]) | (pa[1] ^ pb[1]) | (pa[2] ^ pb[2]) | (pa[3] ^ pb[3])) == 0u);
}

// Grow CPU storage by doubling; the GPU buffer follows at the next RblEndBatch()
static bool rbl__growBatch(rbl__BatchState *batch)
{
    if (batch->capacity >= RBL_MAX_BATCH_BILLBOARDS) return false;
    int newCapacity = (batch->capacity > RBL_MAX_BATCH_BILLBOARDS/2)? RBL_MAX_BATCH_BILLBOARDS : batch->capacity*2;
    if (batch->fade != NULL)
    {
        float *fade = (float *)RBL_REALLOC(batch->fade, (size_t)newCapacity*RBL__FADE_FLOATS*sizeof(float));
        if (fade == NULL) return false;
        batch->fade = fade;
    }
    if (batch->ids != NULL)
    {
        unsigned char *ids = (unsigned char *)RBL_REALLOC(batch->ids, (size_t)newCapacity*RBL__ID_BYTES);
        if (ids == NULL) return false;
        batch->ids = ids;
    }
    if (batch->centres != NULL)
    {
        float *centres = (float *)RBL_REALLOC(batch->centres, (size_t)newCapacity*3*sizeof(float));
        if (centres == NULL) return false;
        batch->centres = centres;
    }
    RblVertex *vertices = (RblVertex *)RBL_REALLOC(batch->vertices, (size_t)newCapacity*4*sizeof(RblVertex));
    if (vertices == NULL) return false;     // the caller logs the skip (a grown fade array is kept: capacity follows later)
    TraceLog(LOG_INFO, "RBL: batch grown from %i to %i billboards (reserve more in RblLoadBatch)", batch->capacity, newCapacity);
    batch->vertices = vertices;
    batch->capacity = newCapacity;
    return true;
}

// The batch an add goes to, or NULL (logged under fn)
static inline rbl__BatchState *rbl__batchForAdd(RblBatch *pub, const char *fn)
{
    rbl__BatchState *batch = rbl__batchState(pub);
    if ((batch == NULL) || !batch->begun || (batch->pass != rbl__passNow()))
    {
        TraceLog(LOG_WARNING, "RBL: %s: %s", fn, (batch == NULL)? "batch not loaded" : !batch->begun? "no RblBeginBatch in progress" :
                 "the batch began in another pass (shadow map, G-buffer or colour): add and end it in the pass it began in");
        return NULL;
    }
    return batch;
}

// How the camera sees the back of a quad of this facing (up and axis tamed): CAMERA_PLANE only with
// a caller up (N = right x up), FIXED cards, AXIS under an orthographic camera (it turns toward the
// camera's position, which a parallel view does not look from); CAMERA_POSITION, and AXIS in
// perspective, face the eye by construction. Culling would drop such a quad: its draw turns culling
// off. n: the plane's normal (PLANE, orthographic: decided here) or the axis (AXIS)
enum { RBL__BACK_NEVER = 0, RBL__BACK_ALWAYS, RBL__BACK_PLANE, RBL__BACK_AXIS };
static int rbl__backMode(const RblCameraFrame *view, int facing, Vector3 up, Vector3 axis, Vector3 *n)
{
    Vector3 a = axis;
    bool noAxis = (a.x == 0.0f) && (a.y == 0.0f) && (a.z == 0.0f);
    if (facing == RBL_FACING_CAMERA_PLANE)
    {
        if ((up.x == 0.0f) && (up.y == 0.0f) && (up.z == 0.0f)) return RBL__BACK_NEVER;
        a = rbl__cross(view->right, up);
    }
    else if (facing == RBL_FACING_FIXED) { if (noAxis) a = rbl__v3(0.0f, 0.0f, 1.0f); }
    else if ((facing == RBL_FACING_AXIS) && view->orthographic) { *n = noAxis? rbl__v3(0.0f, 1.0f, 0.0f) : a; return RBL__BACK_AXIS; }
    else return RBL__BACK_NEVER;
    *n = a;
    if (view->orthographic) return (rbl__dot(a, view->back) < 0.0f)? RBL__BACK_ALWAYS : RBL__BACK_NEVER;
    return RBL__BACK_PLANE;
}

// Whether the camera sees the back at pivot p (mode and n from rbl__backMode)
static inline bool rbl__backAt(const RblCameraFrame *view, int mode, Vector3 n, Vector3 p)
{
    if (mode == RBL__BACK_NEVER) return false;
    if (mode == RBL__BACK_ALWAYS) return true;
    Vector3 toEye = rbl__sub(view->eye, p);
    if (mode == RBL__BACK_PLANE) return rbl__dot(n, toEye) < 0.0f;
    // AXIS: the eye direction off the axis (its degenerate fallbacks face the view)
    float k = rbl__dot(n, toEye)/rbl__dot(n, n);
    return rbl__dot(rbl__v3(toEye.x - n.x*k, toEye.y - n.y*k, toEye.z - n.z*k), view->back) < 0.0f;
}

// Whether the camera sees the back of a quad of this facing at any of n pivots (stride bytes apart)
static bool rbl__showsBack(const RblCameraFrame *view, int facing, Vector3 up, Vector3 axis, const Vector3 *pivots, int n, size_t stride)
{
    Vector3 a = { 0.0f, 0.0f, 0.0f };
    const int mode = rbl__backMode(view, facing, up, axis, &a);
    if ((mode == RBL__BACK_NEVER) || (mode == RBL__BACK_ALWAYS)) return mode == RBL__BACK_ALWAYS;
    for (int i = 0; i < n; i++)
        if (rbl__backAt(view, mode, a, *(const Vector3 *)(const void *)((const unsigned char *)pivots + (size_t)i*stride))) return true;
    return false;
}

// b (after rbl__facingKey) as the batch's next record, in the mapped buffer or the CPU array: written
// once, never read (a mapped buffer is write-only); only the flags the stage reads, a FIXED or AXIS
// up and axis tamed as rbl__facingBasis tames them (their length does not matter there; a GPU
// squaring a huge one would overflow)
RBL__FORCE_INLINE void rbl__storeRecord(rbl__BatchState *batch, const RblBillboard *b)
{
    unsigned char *out = (unsigned char *)((batch->mapped != NULL)? batch->mapped : (rbl__BatchRecord *)(void *)batch->vertices) + (size_t)batch->count*sizeof(rbl__BatchRecord);
    const bool plane = (b->facing == RBL_FACING_CAMERA_PLANE);
    const Vector3 up = plane? b->up : rbl__tame(b->up), axis = plane? b->axis : rbl__tame(b->axis);
    const unsigned int flags = b->flags & (RBL_FRAME_ROTATED | RBL_ROUND_CYLINDER);
    memcpy(out, b, offsetof(RblBillboard, up));
    memcpy(out + offsetof(RblBillboard, up), &up, sizeof(up));
    memcpy(out + offsetof(RblBillboard, axis), &axis, sizeof(axis));
    memcpy(out + offsetof(RblBillboard, roundness), &b->roundness, sizeof(b->roundness));
    memcpy(out + offsetof(RblBillboard, flags), &flags, sizeof(flags));
    // A back seen turns culling off for the draw (a shadow pass draws with it off)
    if (!batch->backFacing && (rbl__state.shadowPass == NULL)) batch->backFacing = rbl__backAt(&batch->view, batch->backMode, batch->backNormal, b->position);
}

// The batch's last run where billboards of material continue it as records, else NULL
RBL__FORCE_INLINE rbl__BatchRun *rbl__recordRun(rbl__BatchState *batch, const Material *material)
{
    if (!batch->records || (batch->count == 0) || (batch->runCount == 0)) return NULL;
    rbl__BatchRun *run = &batch->runs[batch->runCount - 1];
    return rbl__sameMaterial(&run->material, material)? run : NULL;
}

// The common add, kept short: a plain billboard continuing run (rbl__recordRun), whose first add
// settled the material, the stream and the identities. 1 = added, 0 = culled, -1 = not this case
// (the general path takes it: a polygon frame, a full batch, bad input it logs)
RBL__FORCE_INLINE int rbl__addToRecordRun(rbl__BatchState *batch, rbl__BatchRun *run, const RblBillboard *b)
{
    // (the run's texture size passed rbl__billboardOk with its first billboard)
    if ((rbl__polygonHandle(b->flags) != 0u) || (batch->count >= batch->capacity) || (b->facing < RBL_FACING_CAMERA_PLANE) || (b->facing > RBL_FACING_FIXED) || !rbl__billboardWordsOk(b)) return -1;
    rbl__facingKey(batch, b);
    if ((batch->planeCount > 0) && rbl__culled(batch, b)) { batch->culled++; return 0; }
    rbl__storeRecord(batch, b);
    run->count++;
    batch->count++;
    return 1;
}

bool RblBatchAdd(RblBatch *pub, Material material, const RblBillboard *billboard)
{
    rbl__BatchState *batch = rbl__batchForAdd(pub, "RblBatchAdd");
    if (batch == NULL) return false;
    rbl__BatchRun *run = (billboard != NULL)? rbl__recordRun(batch, &material) : NULL;
    bool added = ((run != NULL) && (rbl__addToRecordRun(batch, run, billboard) >= 0)) || rbl__batchAdd(batch, &material, billboard, NULL, "RblBatchAdd");
    pub->capacity = batch->capacity; pub->count = batch->count - batch->extraSlots + batch->culled; pub->skipped = batch->skipped; pub->culled = batch->culled;
    return added;
}

#define RBL__STRETCH_AHEAD 1024      // Bytes ahead of the stretch's reads and writes that it prefetches

#if defined(RBL__SSE2)
// A billboard's 88 bytes as five vectors and its last 8 (roundness, flags)
typedef struct rbl__BillboardWords { __m128i v[5]; __m128i tail; } rbl__BillboardWords;

RBL__FORCE_INLINE rbl__BillboardWords rbl__loadBillboardWords(const unsigned char *q)
{
    rbl__BillboardWords w;
    for (int k = 0; k < 5; k++) w.v[k] = _mm_loadu_si128((const __m128i *)(const void *)(q + 16*k));
    w.tail = _mm_loadl_epi64((const __m128i *)(const void *)(q + 80));
    return w;
}

// w as the record at o, its flags masked by keep (the bits the record stage reads)
RBL__FORCE_INLINE void rbl__storeBillboardWords(unsigned char *o, const rbl__BillboardWords *w, __m128i keep)
{
    for (int k = 0; k < 5; k++) _mm_storeu_si128((__m128i *)(void *)(o + 16*k), w->v[k]);
    _mm_storel_epi64((__m128i *)(void *)(o + 80), _mm_and_si128(w->tail, keep));
}
#endif

// A stretch of billboards continuing run while their facing, up and axis repeat the batch's key
// (rbl__facingKey made it from a billboard that passed every check): rbl__addToRecordRun's steps,
// the key's own checks (facing range, its words' bounds, up and axis stored as given) done once for
// the stretch and what every billboard reads kept in locals (records written through a char pointer
// could alias the batch). Returns how many it took, added or culled; stops at the first the general
// steps must take (another key, a polygon frame, bad input), at most room
RBL__FORCE_INLINE int rbl__addStretch(rbl__BatchState *batch, rbl__BatchRun *run, const RblBillboard *b, int room, int *culledOut)
{
    unsigned int key[7];
    memcpy(key, batch->keyWords, sizeof(key));
    const bool plane = ((int)key[0] == RBL_FACING_CAMERA_PLANE);
    Vector3 up, axis;
    memcpy(&up, key + 1, sizeof(up));
    memcpy(&axis, key + 4, sizeof(axis));
    if (!plane && ((fabsf(up.x) > 1e12f) || (fabsf(up.y) > 1e12f) || (fabsf(up.z) > 1e12f) ||
                   (fabsf(axis.x) > 1e12f) || (fabsf(axis.y) > 1e12f) || (fabsf(axis.z) > 1e12f))) return 0;   // rbl__tame would change them
    unsigned char *out = (unsigned char *)((batch->mapped != NULL)? batch->mapped : (rbl__BatchRecord *)(void *)batch->vertices) + (size_t)batch->count*sizeof(rbl__BatchRecord);
    const bool cull = (batch->planeCount > 0);
    const float heightScale = batch->keyHeightScale, sphereScale = ((batch->planeCount == 4) && ((int)key[0] == RBL_FACING_AXIS))? 9.0f : 1.0f;
    const int backMode = batch->backMode;
    const Vector3 backNormal = batch->backNormal, eye = batch->view.eye;
    bool seekBack = !batch->backFacing && (rbl__state.shadowPass == NULL) && (backMode != RBL__BACK_NEVER);
    int taken = 0, stored = 0, culled = 0;
#if defined(RBL_INSTRUMENTS)
    const long long foursBefore = rbl__state.stretchFours;
#endif
#if defined(RBL__SSE2)
    // Words 13..19 equal the key's, checked when it was made; 12 (tint) is not a float: words 0..11
    // and 20 (roundness) are left to check
    const unsigned int *bias = rbl__billboardWordBias[plane];
    const __m128i expBits = _mm_set1_epi32(0x7f800000), bias0 = _mm_loadu_si128((const __m128i *)(const void *)bias),
                  bias1 = _mm_loadu_si128((const __m128i *)(const void *)(bias + 4)), bias2 = _mm_loadu_si128((const __m128i *)(const void *)(bias + 8));
    const __m128i keyA = _mm_set_epi32((int)key[2], (int)key[1], (int)key[0], 0), keyB = _mm_loadu_si128((const __m128i *)(const void *)(key + 3));
    const __m128i tailKeep = _mm_set_epi32(0, 0, (int)(RBL_FRAME_ROTATED | RBL_ROUND_CYLINDER), -1);
    const unsigned int bias20 = bias[20];
    __m128 planes[4][2];
    for (int e = 0; e < 4; e++) for (int h = 0; h < 2; h++) planes[e][h] = _mm_loadu_ps(&batch->cull[e][4*h]);
    // Four billboards at a time, one per lane for culling and the back test (the same sums, in the
    // same order, as one at a time); a four holding one the stretch stops at goes one at a time
    const int planeCount = cull? batch->planeCount : 0;
    __m128 planeLanes[6][4];
    for (int k = 0; k < planeCount; k++) for (int e = 0; e < 4; e++) planeLanes[k][e] = _mm_set1_ps(batch->cull[e][k]);
    const __m128 absBits = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)), zeroLanes = _mm_setzero_ps(),
                 heightLanes = _mm_set1_ps(heightScale), sphereLanes = _mm_set1_ps(sphereScale), slackLanes = _mm_set1_ps(1.0f + 1e-5f),
                 eyeX = _mm_set1_ps(eye.x), eyeY = _mm_set1_ps(eye.y), eyeZ = _mm_set1_ps(eye.z),
                 normalX = _mm_set1_ps(backNormal.x), normalY = _mm_set1_ps(backNormal.y), normalZ = _mm_set1_ps(backNormal.z);
    const bool laneBack = (backMode == RBL__BACK_PLANE) || (backMode == RBL__BACK_ALWAYS);
    const __m128i tailExp = _mm_set_epi32(0, 0, 0, 0x7f800000), tailBias = _mm_set_epi32(0, 0, 0, (int)bias[20]), tintLane = _mm_set_epi32(0, 0, 0, -1);
    static const unsigned char rbl__laneCount[16] = { 0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4 };
    while ((taken + 4 <= room) && (!seekBack || laneBack))
    {
        const unsigned char *in = (const unsigned char *)b;
        // The hardware's stream prefetch alone leaves the loop waiting on memory (both streams)
        for (int line = 0; line < 4*(int)sizeof(RblBillboard); line += 64)
        {
            _mm_prefetch((const char *)(in + RBL__STRETCH_AHEAD + line), _MM_HINT_T0);
            _mm_prefetch((const char *)(out + RBL__STRETCH_AHEAD + line), _MM_HINT_T0);
        }
        // Lanes: pivot x, y, z and size x, y, origin x, y of the four
        __m128 x = _mm_loadu_ps((const float *)(const void *)in), y = _mm_loadu_ps((const float *)(const void *)(in + sizeof(RblBillboard))),
               z = _mm_loadu_ps((const float *)(const void *)(in + 2*sizeof(RblBillboard))), sizeX = _mm_loadu_ps((const float *)(const void *)(in + 3*sizeof(RblBillboard)));
        _MM_TRANSPOSE4_PS(x, y, z, sizeX);
        __m128 outside = zeroLanes;
        if (planeCount > 0)
        {
            __m128 again = _mm_loadu_ps((const float *)(const void *)(in + 12)), sizeY = _mm_loadu_ps((const float *)(const void *)(in + sizeof(RblBillboard) + 12)),
                   originX = _mm_loadu_ps((const float *)(const void *)(in + 2*sizeof(RblBillboard) + 12)), originY = _mm_loadu_ps((const float *)(const void *)(in + 3*sizeof(RblBillboard) + 12));
            _MM_TRANSPOSE4_PS(again, sizeY, originX, originY);      // (again: size x)
            const __m128 sx = _mm_and_ps(sizeX, absBits), sy = _mm_mul_ps(_mm_and_ps(sizeY, absBits), heightLanes);
            const __m128 ex = _mm_max_ps(_mm_and_ps(originX, absBits), _mm_and_ps(_mm_sub_ps(sx, originX), absBits)),
                         ey = _mm_max_ps(_mm_and_ps(originY, absBits), _mm_and_ps(_mm_sub_ps(sy, originY), absBits));
            const __m128 r2 = _mm_mul_ps(_mm_mul_ps(_mm_add_ps(_mm_mul_ps(ex, ex), _mm_mul_ps(ey, ey)), sphereLanes), slackLanes);
            for (int k = 0; k < planeCount; k++)
            {
                const __m128 d = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(planeLanes[k][0], x), _mm_mul_ps(planeLanes[k][1], y)), _mm_mul_ps(planeLanes[k][2], z)), planeLanes[k][3]);
                outside = _mm_or_ps(outside, _mm_and_ps(_mm_cmplt_ps(d, zeroLanes), _mm_cmpgt_ps(_mm_mul_ps(d, d), r2)));
            }
        }
        const int outMask = _mm_movemask_ps(outside);
        // Each is checked and written where the next record goes; a culled one is written over by
        // the next, and a four that fails a check is not counted (the slots past count are free)
        __m128i carry = _mm_setzero_si128(), same = _mm_set1_epi32(-1);
        unsigned int polygon = 0u;
        unsigned char *o = out;
        for (int l = 0; l < 4; l++)
        {
            const unsigned char *q = in + (size_t)l*sizeof(RblBillboard);
            const rbl__BillboardWords w = rbl__loadBillboardWords(q);
            unsigned int flags;
            memcpy(&flags, q + offsetof(RblBillboard, flags), sizeof(flags));
            carry = _mm_or_si128(carry, _mm_or_si128(_mm_or_si128(_mm_add_epi32(_mm_and_si128(w.v[0], expBits), bias0), _mm_add_epi32(_mm_and_si128(w.v[1], expBits), bias1)),
                                                     _mm_or_si128(_mm_add_epi32(_mm_and_si128(w.v[2], expBits), bias2), _mm_add_epi32(_mm_and_si128(w.tail, tailExp), tailBias))));
            same = _mm_and_si128(same, _mm_and_si128(_mm_or_si128(_mm_cmpeq_epi32(w.v[3], keyA), tintLane), _mm_cmpeq_epi32(w.v[4], keyB)));
            polygon |= rbl__polygonHandle(flags);
            rbl__storeBillboardWords(o, &w, tailKeep);
            o += ((outMask >> l) & 1)? 0 : sizeof(rbl__BatchRecord);
        }
        if ((_mm_movemask_ps(_mm_castsi128_ps(carry)) != 0) || (_mm_movemask_epi8(same) != 0xffff) || (polygon != 0u)) break;
        const int kept = 4 - rbl__laneCount[outMask];
        out = o;
        stored += kept;
        culled += 4 - kept;
        if (seekBack && (kept > 0))
        {
            // rbl__backAt's PLANE test: n . (eye - p) < 0, in rbl__dot's order
            const __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(normalX, _mm_sub_ps(eyeX, x)), _mm_mul_ps(normalY, _mm_sub_ps(eyeY, y))), _mm_mul_ps(normalZ, _mm_sub_ps(eyeZ, z)));
            const int backMask = ((backMode == RBL__BACK_ALWAYS)? 15 : _mm_movemask_ps(_mm_cmplt_ps(d, zeroLanes))) & ~outMask;
            if (backMask != 0) { batch->backFacing = true; seekBack = false; }
        }
        taken += 4;
        b += 4;
#if defined(RBL_INSTRUMENTS)
        rbl__state.stretchFours++;
#endif
    }
#endif
    for (; taken < room; taken++, b++)
    {
        const unsigned char *in = (const unsigned char *)b;
        Vector3 position;
        Vector2 size, origin;
        memcpy(&position, in + offsetof(RblBillboard, position), sizeof(position));
        memcpy(&size, in + offsetof(RblBillboard, size), sizeof(size));
        memcpy(&origin, in + offsetof(RblBillboard, origin), sizeof(origin));
#if defined(RBL__SSE2)
        const rbl__BillboardWords w = rbl__loadBillboardWords(in);
        const __m128i carry = _mm_or_si128(_mm_or_si128(_mm_add_epi32(_mm_and_si128(w.v[0], expBits), bias0), _mm_add_epi32(_mm_and_si128(w.v[1], expBits), bias1)),
                                           _mm_add_epi32(_mm_and_si128(w.v[2], expBits), bias2));
        const unsigned int roundness = (unsigned int)_mm_cvtsi128_si32(w.tail), flags = (unsigned int)_mm_cvtsi128_si32(_mm_srli_si128(w.tail, 4));
        const int same = (_mm_movemask_epi8(_mm_cmpeq_epi32(w.v[3], keyA)) | 0xf) & _mm_movemask_epi8(_mm_cmpeq_epi32(w.v[4], keyB));
        if ((same != 0xffff) || (_mm_movemask_ps(_mm_castsi128_ps(carry)) != 0) || ((((roundness & 0x7f800000u) + bias20) & 0x80000000u) != 0u) ||
            (rbl__polygonHandle(flags) != 0u)) break;
#else
        unsigned int w[7], flags;
        memcpy(w, in + offsetof(RblBillboard, facing), sizeof(w));
        memcpy(&flags, in + offsetof(RblBillboard, flags), sizeof(flags));
        if ((((w[0] ^ key[0]) | (w[1] ^ key[1]) | (w[2] ^ key[2]) | (w[3] ^ key[3]) | (w[4] ^ key[4]) | (w[5] ^ key[5]) | (w[6] ^ key[6])) != 0u) ||
            (rbl__polygonHandle(flags) != 0u) || !rbl__billboardWordsOk(b)) break;
#endif
        if (cull)
        {
            // rbl__culled's sums, in its order
            float sx = fabsf(size.x), sy = fabsf(size.y)*heightScale;
            float ax = fabsf(origin.x), bx = fabsf(sx - origin.x), ay = fabsf(origin.y), by = fabsf(sy - origin.y);
            float ex = (ax > bx)? ax : bx, ey = (ay > by)? ay : by;
            float r2 = (ex*ex + ey*ey)*sphereScale;
            r2 *= 1.0f + 1e-5f;
#if defined(RBL__SSE2)
            const __m128 x = _mm_set1_ps(position.x), y = _mm_set1_ps(position.y), z = _mm_set1_ps(position.z), r = _mm_set1_ps(r2), zero = _mm_setzero_ps();
            __m128 outside = zero;
            for (int h = 0; h < 2; h++)
            {
                __m128 d = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(planes[0][h], x), _mm_mul_ps(planes[1][h], y)), _mm_mul_ps(planes[2][h], z)), planes[3][h]);
                outside = _mm_or_ps(outside, _mm_and_ps(_mm_cmplt_ps(d, zero), _mm_cmpgt_ps(_mm_mul_ps(d, d), r)));
            }
            if (_mm_movemask_ps(outside) != 0) { culled++; continue; }
#else
            if (rbl__outsidePlanesScalar((const float (*)[8])batch->cull, position, r2)) { culled++; continue; }
#endif
        }
#if defined(RBL__SSE2)
        rbl__storeBillboardWords(out, &w, tailKeep);
#else
        flags &= (RBL_FRAME_ROTATED | RBL_ROUND_CYLINDER);
        memcpy(out, in, offsetof(RblBillboard, flags));
        memcpy(out + offsetof(RblBillboard, flags), &flags, sizeof(flags));
#endif
        out += sizeof(rbl__BatchRecord);
        stored++;
        if (seekBack)
        {
            // rbl__backAt's test, its PLANE case with the values in locals
            const bool back = (backMode == RBL__BACK_ALWAYS) ||
                              ((backMode == RBL__BACK_PLANE)? (rbl__dot(backNormal, rbl__sub(eye, position)) < 0.0f) : rbl__backAt(&batch->view, backMode, backNormal, position));
            if (back) { batch->backFacing = true; seekBack = false; }
        }
    }
    run->count += stored;
    batch->count += stored;
    *culledOut += culled;
#if defined(RBL_INSTRUMENTS)
    rbl__state.stretchSingles += taken - 4*(rbl__state.stretchFours - foursBefore);
#endif
    return taken;
}

int RblBatchAddMany(RblBatch *pub, Material material, const RblBillboard *billboards, int count)
{
    rbl__BatchState *batch = rbl__batchForAdd(pub, "RblBatchAddMany");
    if (batch == NULL) return 0;
    if ((count < 0) || ((count > 0) && (billboards == NULL)))
    {
        TraceLog(LOG_WARNING, "RBL: RblBatchAddMany: %s", (count < 0)? "negative count" : "NULL billboards");
        return 0;
    }
    int added = 0;
    for (int i = 0; i < count; )
    {
        rbl__BatchRun *run = rbl__recordRun(batch, &material);
        int r = (run != NULL)? rbl__addToRecordRun(batch, run, &billboards[i]) : -1;
        if (r < 0) r = rbl__batchAdd(batch, &material, &billboards[i], NULL, "RblBatchAddMany")? 1 : 0;
        else r = 1;
        added += r;
        i++;
        // The billboards after it that repeat its key go in one stretch
        run = ((i < count) && batch->keyValid)? rbl__recordRun(batch, &material) : NULL;
        if (run != NULL)
        {
            int room = batch->capacity - batch->count, culled = 0;
            if (room > count - i) room = count - i;
            int taken = rbl__addStretch(batch, run, &billboards[i], room, &culled);
            batch->culled += culled;
            added += taken;
            i += taken;
        }
    }
    pub->capacity = batch->capacity; pub->count = batch->count - batch->extraSlots + batch->culled; pub->skipped = batch->skipped; pub->culled = batch->culled;
    return added;
}

// The cross-fade's own entry point: the plain path above never reads or checks fade data
bool RblBatchAddFade(RblBatch *pub, Material material, const RblBillboard *billboard, const RblFade *fade)
{
    rbl__BatchState *batch = rbl__batchForAdd(pub, "RblBatchAddFade");
    if (batch == NULL) return false;
    bool added = false;
    if ((fade == NULL) || !rbl__fadeOk(fade, RBL__BILLBOARD_LIMIT_EXPONENT))
    {
        if (batch->skipped++ == 0) TraceLog(LOG_WARNING, "RBL: RblBatchAddFade: billboard skipped (%s); further skips this batch are not logged", (fade == NULL)? "NULL fade" : "fade weight outside 0..1, NaN/Inf or huge source, or bad clip");
    }
    else added = rbl__batchAdd(batch, &material, billboard, fade, "RblBatchAddFade");
    pub->capacity = batch->capacity; pub->count = batch->count - batch->extraSlots + batch->culled; pub->skipped = batch->skipped; pub->culled = batch->culled;
    return added;
}

// Whether a run of program's material can draw from records (the header's vertex stage expands them):
// GLSL 3, and a shadow pass (its casters draw every material) or a lit program without cross-fades
static bool rbl__recordable(const rbl__Program *program)
{
    if (rbl__glsl() < 300) return false;
    if (rbl__state.shadowPass != NULL) return true;
    return (program != NULL) && !program->key.desc.crossFade;        // (skinned programs never draw billboards)
}

// Record i (of run r) as the vertex path's four vertices (cache: the batch's frame, or a fresh one).
// out may overlap the records: the record is read first
static void rbl__recordVertices(const rbl__BatchState *batch, int r, int i, rbl__FrameCache *cache, RblVertex out[4])
{
    const rbl__BatchRecord b = ((const rbl__BatchRecord *)(const void *)batch->vertices)[i];
    const rbl__Cast *cast = (rbl__state.shadowPass != NULL)? &rbl__state.cast : NULL;
    rbl__expandQuad(&batch->view, cast, cache, batch->runs[r].textureWidth, batch->runs[r].textureHeight, &b, NULL, out, NULL);
}

// Slot's caster identity for the vertex stream: per vertex its high and low bytes, two zero bytes
static void rbl__writeCasterIds(unsigned char *o, const RblBillboard *b, int slots)
{
    unsigned int id = rbl__casterId(b->position, b->size, b->origin);
    for (int v = 0; v < 4*slots; v++) { o[4*v] = (unsigned char)(id >> 8); o[4*v + 1] = (unsigned char)(id & 255u); o[4*v + 2] = o[4*v + 3] = 0; }
}

// Turns the batch's records into vertices in place, last first (record i lies below vertex slot i),
// with their identities where the batch has the stream
static void rbl__recordsToVertices(rbl__BatchState *batch)
{
    rbl__recordsToCpu(batch);
    for (int i = 0; batch->identified && (i < batch->count); i++)
        rbl__writeCasterIds(batch->ids + (size_t)i*RBL__ID_BYTES, (const rbl__BatchRecord *)(const void *)batch->vertices + i, 1);
    for (int r = batch->runCount - 1; r >= 0; r--)
        for (int i = batch->runs[r].first + batch->runs[r].count - 1; i >= batch->runs[r].first; i--)
            rbl__recordVertices(batch, r, i, &batch->frame, batch->vertices + (size_t)i*4);
    batch->records = false;
}

// fade: NULL for a plain billboard (checked by the caller otherwise)
static bool rbl__batchAdd(rbl__BatchState *batch, const Material *material, const RblBillboard *billboard, const RblFade *fade, const char *fn)
{
    // A polygon frame takes its slots (a cross-fade draws the quad: the union of two frames' trims)
    const rbl__Polygon *poly = NULL;
    const bool polyKnown = (billboard == NULL) || (fade != NULL) || rbl__billboardPolygon(billboard->flags, &poly);
    const int slots = (billboard != NULL)? rbl__slotCount(poly, billboard) : 1;
    if ((batch->count + slots > batch->capacity) && batch->onGpu) rbl__recordsToCpu(batch);      // the array grows with them
    while (batch->count + slots > batch->capacity)
        if (!rbl__growBatch(batch))
        {
            if (batch->skipped++ == 0) TraceLog(LOG_WARNING, "RBL: %s: batch full at %i billboards (limit %i or out of memory); further skips this batch are not logged", fn, batch->capacity, RBL_MAX_BATCH_BILLBOARDS);
            return false;
        }

    rbl__BatchRun *run = (batch->runCount > 0)? &batch->runs[batch->runCount - 1] : NULL;
    const bool newRun = (run == NULL) || !rbl__sameMaterial(&run->material, material);
    rbl__Program *program = NULL;
    const char *bad = (billboard == NULL)? "NULL billboard" : newRun? rbl__materialProblem(material, RBL__PATH_BILLBOARD, &program) : NULL;
    int texW = 1, texH = 1;
    if ((bad == NULL) && newRun) rbl__albedoSize(material, &texW, &texH);       // the maps are read once the shader is known live
    else if (bad == NULL) { texW = run->textureWidth; texH = run->textureHeight; }   // the same maps (rbl__sameMaterial)
    if ((bad == NULL) && !rbl__billboardOk(billboard, texW, texH)) bad = "NaN/Inf or huge input, or bad facing";
    if ((bad == NULL) && !polyKnown) bad = "its RBL_FRAME_POLYGON bits name no loaded atlas's polygon (unloaded atlas?)";
    if (bad == NULL) rbl__facingKey(batch, billboard);
    if ((bad == NULL) && (batch->planeCount > 0) && rbl__culled(batch, billboard)) { batch->culled++; return true; }
    float centre[3] = { 0.0f, 0.0f, 0.0f };
    // Records from the first billboard where every run can draw them; a billboard they cannot hold
    // turns the batch back to vertices
    if ((bad == NULL) && (batch->count == 0)) batch->records = !batch->vertexOnly && (poly == NULL) && (fade == NULL) && rbl__recordable(program);
    else if ((bad == NULL) && batch->records && ((poly != NULL) || (fade != NULL) || (newRun && !rbl__recordable(program)))) rbl__recordsToVertices(batch);
    if ((bad == NULL) && (batch->count == 0) && batch->records && batch->mapOk && (batch->mapped == NULL)) rbl__mapRecords(batch);
    const rbl__Cast *cast = (rbl__state.shadowPass != NULL)? &rbl__state.cast : NULL;
    if ((bad == NULL) && batch->records) rbl__storeRecord(batch, billboard);
    else if ((bad == NULL) && !rbl__expandQuad(&batch->view, cast, &batch->frame, texW, texH, billboard, poly, batch->vertices + (size_t)batch->count*4, centre))
        bad = "NaN/Inf or huge input, or bad facing";
    if ((bad == NULL) && (poly != NULL) && !batch->polygonal)
    {
        // The sort keys of the slots so far: each a quad's own centre
        if (batch->centres == NULL) batch->centres = (float *)RBL_MALLOC((size_t)batch->capacity*3*sizeof(float));
        if (batch->centres == NULL) bad = "out of memory for the polygon slots' sort keys";
        for (int i = 0; (bad == NULL) && (i < batch->count); i++)
        {
            const RblVertex *v = batch->vertices + (size_t)i*4;
            for (int e = 0; e < 3; e++) batch->centres[3*i + e] = 0.25f*(v[0].position[e] + v[1].position[e] + v[2].position[e] + v[3].position[e]);
        }
        if (bad == NULL) batch->polygonal = true;
    }
    if (bad != NULL)
    {
        if (batch->skipped++ == 0) TraceLog(LOG_WARNING, "RBL: %s: billboard skipped (%s); further skips this batch are not logged", fn, bad);
        return false;
    }
    // The identity stream starts with the first billboard cast into a casters target or drawn by a
    // shadow receiver (forward, or into a G-buffer that receives shadows); earlier ones get 0 (their
    // programs read none). Continuing runs had their program checked when they started. Records
    // leave it unwritten (the record stage hashes each billboard itself) until they turn to vertices.
    const RblShadowMap *pass = rbl__state.shadowPass;
    const RblGBuffer *gpass = rbl__state.gbufferPass;
    if (batch->identified || ((pass != NULL)? !pass->desc.selfShadow : (gpass != NULL)? (gpass->desc.shading.shadowMaps > 0) :
                                                                        ((program != NULL) && (program->key.desc.shading.shadowMaps > 0))))
    {
        if (batch->ids == NULL) batch->ids = (unsigned char *)RBL_MALLOC((size_t)batch->capacity*RBL__ID_BYTES);
        if (batch->ids == NULL)
        {
            if (batch->skipped++ == 0) TraceLog(LOG_WARNING, "RBL: %s: billboard skipped (out of memory for the caster identities); further skips this batch are not logged", fn);
            return false;
        }
        if (!batch->identified && !batch->records) memset(batch->ids, 0, (size_t)batch->count*RBL__ID_BYTES);
        batch->identified = true;
        if (!batch->records) rbl__writeCasterIds(batch->ids + (size_t)batch->count*RBL__ID_BYTES, billboard, slots);
    }
    // The fade stream starts with the first faded billboard (earlier ones get weight 0); a clipped
    // one at weight 0 needs it too (its quad is the union of two trims: only the first's is drawn).
    // Plain billboards after it get weight 0 and no clip (zeros)
    if ((fade != NULL) && !batch->fading && !(fade->weight > 0.0f) && (fade->clip[0].width == 0.0f) && (fade->clip[0].height == 0.0f) &&
        (fade->clip[1].width == 0.0f) && (fade->clip[1].height == 0.0f)) fade = NULL;       // nothing to draw yet: no stream
    if ((fade != NULL) || batch->fading)
    {
        if (batch->fade == NULL) batch->fade = (float *)RBL_MALLOC((size_t)batch->capacity*RBL__FADE_FLOATS*sizeof(float));
        if (batch->fade == NULL)
        {
            if (batch->skipped++ == 0) TraceLog(LOG_WARNING, "RBL: %s: billboard skipped (out of memory for the fade stream); further skips this batch are not logged", fn);
            return false;
        }
        if (!batch->fading) memset(batch->fade, 0, (size_t)batch->count*RBL__FADE_FLOATS*sizeof(float));
        batch->fading = true;
        float *row = batch->fade + (size_t)batch->count*RBL__FADE_FLOATS;
        if (fade != NULL) rbl__fadeVertices(billboard, fade, texW, texH, row);
        else memset(row, 0, (size_t)slots*RBL__FADE_FLOATS*sizeof(float));
    }
    if (batch->polygonal)
        for (int i = 0; i < slots; i++)
        {
            float *c = batch->centres + 3*((size_t)batch->count + i);
            if (poly != NULL) { c[0] = centre[0]; c[1] = centre[1]; c[2] = centre[2]; }
            else
            {
                const RblVertex *v = batch->vertices + (size_t)batch->count*4;
                for (int e = 0; e < 3; e++) c[e] = 0.25f*(v[0].position[e] + v[1].position[e] + v[2].position[e] + v[3].position[e]);
            }
        }
    // The quad is planar: the camera sees its back when it lies behind the plane (perspective) or
    // looks along the normal (orthographic). Culling would drop it (FIXED cards, a reversed caller up)
    // (records: rbl__showsBack above)
    if (!batch->backFacing && !batch->records)
    {
        Vector3 toViewer = batch->orthographic? batch->view.back : rbl__sub(batch->view.eye, billboard->position);
        if (rbl__dot(batch->frame.normal, toViewer) < 0.0f) batch->backFacing = true;
    }

    if (newRun)
    {
        if (batch->runCount == batch->runCapacity)
        {
            rbl__BatchRun *runs = (rbl__BatchRun *)RBL_REALLOC(batch->runs, (size_t)batch->runCapacity*2*sizeof(rbl__BatchRun));
            if (runs == NULL) { TraceLog(LOG_WARNING, "RBL: batch: out of memory for material runs"); return false; }
            batch->runs = runs;
            batch->runCapacity *= 2;
        }
        run = &batch->runs[batch->runCount++];
        run->material = *material;
        run->first = batch->count;
        run->count = 0;
        run->textureWidth = texW; run->textureHeight = texH;
    }
    run->count += slots;
    batch->count += slots;
    batch->extraSlots += slots - 1;
    return true;
}

// Bind the material the way raylib's DrawMesh does (same uniform names and texture slots); returns
// the texture slots bound (bit i = slot i) for rbl__unbindMaterial
static unsigned int rbl__bindMaterial(const Material *material)
{
    Shader sh = material->shader;
    rlEnableShader(sh.id);
    Matrix view = rlGetMatrixModelview(), proj = rlGetMatrixProjection();
    // Billboard vertices are already in world space: model = identity (the seed applied it twice)
    if (sh.locs[SHADER_LOC_MATRIX_MVP] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_MVP], rbl__matMul(view, proj));
    if (sh.locs[SHADER_LOC_MATRIX_MODEL] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_MODEL], rbl__identity());
    if (sh.locs[SHADER_LOC_MATRIX_NORMAL] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_NORMAL], rbl__identity());
    if (sh.locs[SHADER_LOC_MATRIX_VIEW] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_VIEW], view);
    if (sh.locs[SHADER_LOC_MATRIX_PROJECTION] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_PROJECTION], proj);
    if (sh.locs[SHADER_LOC_COLOR_DIFFUSE] != -1)
    {
        Color c = material->maps[MATERIAL_MAP_ALBEDO].color;
        float v[4] = { c.r/255.0f, c.g/255.0f, c.b/255.0f, c.a/255.0f };
        rlSetUniform(sh.locs[SHADER_LOC_COLOR_DIFFUSE], v, SHADER_UNIFORM_VEC4, 1);
    }
    // Slots 0..5 (albedo .. emission), as raylib's DrawMesh: only maps the shader samples are bound.
    // Sampler uniforms are set on every draw: a cache keyed by shader id would go stale when GL
    // reuses the id of an unloaded program.
    unsigned int bound = 0;
    for (int i = MATERIAL_MAP_ALBEDO; i <= MATERIAL_MAP_EMISSION; i++)
    {
        int loc = sh.locs[SHADER_LOC_MAP_DIFFUSE + i];
        unsigned int id = material->maps[i].texture.id;
        if ((i == MATERIAL_MAP_ALBEDO) && (id == 0)) id = rlGetTextureIdDefault();
        if ((id == 0) || (loc == -1)) continue;
        rlActiveTextureSlot(i);
        rlEnableTexture(id);
        rlSetUniform(loc, &i, SHADER_UNIFORM_INT, 1);
        bound |= 1u << i;
    }
    return bound;
}

// Unbind the slots rbl__bindMaterial bound (each GL call costs ~0.1 us; a small batch feels 12 of
// them), leaving slot 0 active as raylib expects
static void rbl__unbindMaterial(unsigned int bound)
{
    for (int i = MATERIAL_MAP_EMISSION; i > MATERIAL_MAP_ALBEDO; i--)
        if (bound & (1u << i)) { rlActiveTextureSlot(i); rlDisableTexture(); }
    rlActiveTextureSlot(0);
    if (bound & 1u) rlDisableTexture();
    rlDisableShader();
}

static void rbl__setVertexLayout(size_t baseOffset)
{
    const int stride = (int)sizeof(RblVertex);
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION, 3, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, position)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD, 2, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, texcoord)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_NORMAL, 3, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, normal)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TANGENT, 4, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, tangent)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_COLOR, 4, RL_UNSIGNED_BYTE, true, stride, (int)(baseOffset + offsetof(RblVertex, color)));
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_NORMAL);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TANGENT);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_COLOR);
}

// RblEndBatch under the name of the public call it serves (refusals are logged with that name)
static void rbl__endBatch(RblBatch *batch, const char *fn);

void RblEndBatch(RblBatch *batch) { rbl__endBatch(batch, "RblEndBatch"); }

// ---- the draw skeleton the batch and instanced paths share ----

// A per-item stream made on first use (fades, caster identities), at least capacity items of
// bytesEach; false when it cannot be created (logged; the old buffer kept, nothing drawn)
static bool rbl__reserveStream(unsigned int *vbo, int *gpuCapacity, int capacity, int bytesEach, const char *fn, const char *what)
{
    if (*gpuCapacity >= capacity) return true;
    unsigned int id = rlLoadVertexBuffer(NULL, capacity*bytesEach, true);
    if (id == 0) { TraceLog(LOG_WARNING, "RBL: %s: GPU %s buffer for %i items could not be created; nothing drawn", fn, what, capacity); return false; }
    if (*vbo != 0) rlUnloadVertexBuffer(*vbo);
    *vbo = id;
    *gpuCapacity = capacity;
    return true;
}

// One layer of a draw (every material run of a batch, the instances of one call)
typedef void (*rbl__DrawLayer)(void *context);

// The layers a sort mode draws: hybrid = texels at or above solid alpha as opaque geometry (depth
// written), then the fringe over everything behind it, depth tested but not written (depth writes
// end on: raylib's default); other modes one layer. Each layer re-applies its material values, which
// carry the alpha band.
static void rbl__drawLayers(int sort, float solidAlpha, rbl__DrawLayer draw, void *context)
{
    if (sort != RBL_SORT_HYBRID) { draw(context); return; }
    const float solid = (solidAlpha == 0.0f)? 1.0f : solidAlpha;
    rbl__state.alphaBand.x = solid; rbl__state.alphaBand.y = 2.0f;
    draw(context);
    rlDisableDepthMask();
    rbl__state.alphaBand.x = 0.0f; rbl__state.alphaBand.y = solid;
    draw(context);
    rlEnableDepthMask();
    rbl__state.alphaBand.x = 0.0f; rbl__state.alphaBand.y = 0.0f;
}

// Sort keys: farther first; equal depths keep submission order (a total order: any submission order
// of distinct depths draws alike)
static int rbl__compareKeys(const void *a, const void *b)
{
    const rbl__SortKey *p = (const rbl__SortKey *)a, *q = (const rbl__SortKey *)b;
    if (p->depth != q->depth) return (p->depth > q->depth)? -1 : 1;
    return (p->index > q->index) - (p->index < q->index);
}

// Sort scratch of a batch or an instance buffer: a sorted copy (itemSize bytes per item) and keys for
// capacity items, reallocated only when the capacity grew (never per frame); false when out of memory
static bool rbl__reserveSort(void **sorted, size_t itemSize, rbl__SortKey **keys, int *have, int capacity)
{
    if (*have >= capacity) return true;
    void *items = RBL_MALLOC((size_t)capacity*itemSize);
    rbl__SortKey *k = (rbl__SortKey *)RBL_MALLOC((size_t)capacity*sizeof(rbl__SortKey));
    if ((items == NULL) || (k == NULL)) { RBL_FREE(items); RBL_FREE(k); return false; }
    RBL_FREE(*sorted); RBL_FREE(*keys);
    *sorted = items; *keys = k;
    *have = capacity;
    return true;
}

// Orders the batch's quads back to front into batch->sorted (keys: their view depths, indices, runs);
// false when the scratch cannot be allocated (the caller logs and draws in submission order)
static bool rbl__sortBatch(rbl__BatchState *batch)
{
    void *sorted = batch->sorted;
    bool reserved = rbl__reserveSort(&sorted, 4*sizeof(RblVertex), &batch->keys, &batch->sortCapacity, batch->capacity);
    batch->sorted = (RblVertex *)sorted;
    if (!reserved) return false;
    // Depth of the quad's centre along the view direction (-back): the same axis for both projections
    Vector3 back = batch->view.back, eye = batch->view.eye;
    for (int r = 0; r < batch->runCount; r++)
        for (int i = batch->runs[r].first; i < batch->runs[r].first + batch->runs[r].count; i++)
        {
            // A record's corners are the vertex stage's: the CPU's expansion gives the same centre
            RblVertex corners[4];
            const RblVertex *v = batch->vertices + (size_t)i*4;
            if (batch->records) { rbl__recordVertices(batch, r, i, &batch->frame, corners); v = corners; }
            Vector3 c = rbl__v3(0.25f*(v[0].position[0] + v[1].position[0] + v[2].position[0] + v[3].position[0]),
                                0.25f*(v[0].position[1] + v[1].position[1] + v[2].position[1] + v[3].position[1]),
                                0.25f*(v[0].position[2] + v[1].position[2] + v[2].position[2] + v[3].position[2]));
            if (batch->polygonal) c = rbl__v3(batch->centres[3*i], batch->centres[3*i + 1], batch->centres[3*i + 2]);   // a polygon's slots sort as its quad
            batch->keys[i].depth = -rbl__dot(rbl__sub(c, eye), back);
            batch->keys[i].index = i;
            batch->keys[i].run = r;
        }
    qsort(batch->keys, (size_t)batch->count, sizeof(rbl__SortKey), rbl__compareKeys);
    const size_t each = batch->records? sizeof(rbl__BatchRecord) : 4*sizeof(RblVertex);
    for (int i = 0; i < batch->count; i++) memcpy((unsigned char *)batch->sorted + (size_t)i*each, (const unsigned char *)batch->vertices + (size_t)batch->keys[i].index*each, each);
    if (batch->identified && !batch->records)
    {
        if (batch->idSortCapacity < batch->capacity)
        {
            unsigned char *s = (unsigned char *)RBL_MALLOC((size_t)batch->capacity*RBL__ID_BYTES);
            if (s == NULL) return false;
            RBL_FREE(batch->idsSorted);
            batch->idsSorted = s;
            batch->idSortCapacity = batch->capacity;
        }
        for (int i = 0; i < batch->count; i++) memcpy(batch->idsSorted + (size_t)i*RBL__ID_BYTES, batch->ids + (size_t)batch->keys[i].index*RBL__ID_BYTES, RBL__ID_BYTES);
    }
    if (!batch->fading) return true;
    if (batch->fadeSortCapacity < batch->capacity)
    {
        float *f = (float *)RBL_MALLOC((size_t)batch->capacity*RBL__FADE_FLOATS*sizeof(float));
        if (f == NULL) return false;
        RBL_FREE(batch->fadeSorted);
        batch->fadeSorted = f;
        batch->fadeSortCapacity = batch->capacity;
    }
    for (int i = 0; i < batch->count; i++) memcpy(batch->fadeSorted + (size_t)i*RBL__FADE_FLOATS, batch->fade + (size_t)batch->keys[i].index*RBL__FADE_FLOATS, RBL__FADE_FLOATS*sizeof(float));
    return true;
}

// The record stream's vertex array, made on first use (left unbound); false when it cannot be made.
// Its pointers are set per draw
static bool rbl__makeRecordArray(rbl__BatchState *batch)
{
    if (batch->recordVaoId == 0)
    {
        batch->recordVaoId = rlLoadVertexArray();
        rlDisableVertexArray();
    }
    return batch->recordVaoId != 0;
}

// Points the record inputs (lit_instanced.vs.glsl rblRecord*) at records [first, ...) of the
// batch's buffer, one per instance
static void rbl__setRecordLayout(const rbl__BatchState *batch, int first)
{
    static const struct { unsigned int location; int size, type, offset; bool normalised; } in[10] = {
        { 10, 3, RL_FLOAT, (int)offsetof(RblBillboard, position), false }, { 11, 4, RL_FLOAT, (int)offsetof(RblBillboard, size), false },
        { 12, 1, RL_FLOAT, (int)offsetof(RblBillboard, rotation), false }, { 13, 4, RL_FLOAT, (int)offsetof(RblBillboard, source), false },
        { 14, 4, RL_UNSIGNED_BYTE, (int)offsetof(RblBillboard, tint), true }, { 15, 1, 0x1404 /* GL_INT */, (int)offsetof(RblBillboard, facing), false },
        { 6, 3, RL_FLOAT, (int)offsetof(RblBillboard, up), false }, { 7, 3, RL_FLOAT, (int)offsetof(RblBillboard, axis), false },
        { 8, 1, RL_FLOAT, (int)offsetof(RblBillboard, roundness), false }, { 9, 1, 0x1405 /* GL_UNSIGNED_INT */, (int)offsetof(RblBillboard, flags), false } };
    rlEnableVertexBuffer(batch->vboId);
    for (int a = 0; a < 10; a++)
    {
        rlSetVertexAttribute(in[a].location, in[a].size, in[a].type, in[a].normalised, (int)sizeof(rbl__BatchRecord), (int)((size_t)first*sizeof(rbl__BatchRecord)) + in[a].offset);
        rlSetVertexAttributeDivisor(in[a].location, 1);
        rlEnableVertexAttribute(in[a].location);
    }
}

static void rbl__instancingFrame(const RblInstancedDesc *desc, const RblCameraFrame *view, int texW, int texH, float frame[32]);

// The instanced stage's per-draw frame for run r's records: each record has its own facing, up, axis
// and roundness; the code carries the pass's bits (lit_instanced.vs.glsl)
static void rbl__recordFrame(const rbl__BatchState *batch, int r, float frame[32])
{
    RblInstancedDesc none;
    memset(&none, 0, sizeof(none));
    rbl__instancingFrame(&none, &batch->view, batch->runs[r].textureWidth, batch->runs[r].textureHeight, frame);
    frame[3] = (float)((rbl__state.cast.faceLight? 8 : 0) + (rbl__state.cast.radial? 16 : 0));
}

// Draws quads [first, first + count) of the bound vertex buffer with run r's material
static void rbl__drawBatchQuads(const rbl__BatchState *batch, int r, int first, int count, const char *fn, unsigned int *bound)
{
    MaterialMap casterMaps[RBL__CASTER_MAPS];
    Material material = batch->runs[r].material;
    rbl__Program *program = NULL;
    if (!rbl__prepareDraw(&material, casterMaps, RBL__PATH_BILLBOARD, batch->fading, batch->records, fn, &program)) return;
    *bound |= rbl__bindMaterial(&material);
    if (program != NULL) rbl__applyMaterialValues(program, &material);
    if (!batch->fading && (program != NULL) && program->key.desc.crossFade)
    {
        // No stream: the attribute is constant, weight 0 (the first frame alone), never stale data
        const float none[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        rlDisableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD2);
        rlSetVertexAttributeDefault(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD2, none, SHADER_ATTRIB_VEC4, 4);
        if (program->fadeClipLoc >= 0)
        {
            rlDisableVertexAttribute((unsigned int)program->fadeClipLoc);      // constant 0: inside both (unclipped)
            rlSetVertexAttributeDefault(program->fadeClipLoc, none, SHADER_ATTRIB_VEC4, 4);
        }
    }
    const int clipLoc = (batch->fading && (program != NULL))? program->fadeClipLoc : -1;
    // Caster identities: the stream where the batch has one (the gate on), else identity 0 (gate off:
    // the attribute's content does not matter)
    const int idLoc = (batch->identified && (program != NULL))? program->casterIdLoc : -1;
    if ((program != NULL) && (program->casterIdLoc >= 0))
    {
        float on = batch->identified? 1.0f : 0.0f;
        rlSetUniform(program->loc[RBL__U_CASTER_ID_ON], &on, SHADER_UNIFORM_FLOAT, 1);
        if (!batch->identified) rlDisableVertexAttribute((unsigned int)program->casterIdLoc);
    }
    if (batch->records)
    {
        float frame[32];
        rbl__recordFrame(batch, r, frame);
        rlSetUniform(program->loc[RBL__U_INSTANCING], frame, SHADER_UNIFORM_VEC4, 7);
        rbl__setRecordLayout(batch, first);
        rlDrawVertexArrayInstanced(0, 6, count);
    }
    for (int q = 0; !batch->records && (q < count); q += RBL__QUADS_PER_CHUNK)
    {
        int n = count - q;
        if (n > RBL__QUADS_PER_CHUNK) n = RBL__QUADS_PER_CHUNK;
        rbl__setVertexLayout((size_t)(first + q)*4*sizeof(RblVertex));
        if (idLoc >= 0)
        {
            rlEnableVertexBuffer(batch->idVboId);
            rlSetVertexAttribute((unsigned int)idLoc, 4, RL_UNSIGNED_BYTE, true, 4, (int)((size_t)(first + q)*RBL__ID_BYTES));
            rlEnableVertexAttribute((unsigned int)idLoc);
            rlEnableVertexBuffer(batch->vboId);
        }
        if (batch->fading)
        {
            rlEnableVertexBuffer(batch->fadeVboId);
            const int stride = RBL__FADE_VERTEX_FLOATS*(int)sizeof(float);
            const size_t at = (size_t)(first + q)*RBL__FADE_FLOATS*sizeof(float);
            rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD2, 4, RL_FLOAT, false, stride, (int)at);
            rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD2);
            if (clipLoc >= 0)
            {
                rlSetVertexAttribute((unsigned int)clipLoc, 4, RL_FLOAT, false, stride, (int)(at + 4*sizeof(float)));
                rlEnableVertexAttribute((unsigned int)clipLoc);
            }
            rlEnableVertexBuffer(batch->vboId);     // the next chunk's layout reads the bound buffer
        }
        rlDrawVertexArrayElements(0, n*6, 0);
    }
    if ((program != NULL) && (program->casterIdLoc >= 0))
    {
        // raylib's own DrawModel may draw with this program next: identity 0 for it
        float off = 0.0f;
        rlSetUniform(program->loc[RBL__U_CASTER_ID_ON], &off, SHADER_UNIFORM_FLOAT, 1);
        if (idLoc >= 0) rlDisableVertexAttribute((unsigned int)idLoc);
    }
    if (program != NULL) rbl__markDrawn(program);
}

// One pass over the uploaded quads: the runs in order, or (sorted) each stretch of consecutive
// sorted quads that share a run
static void rbl__drawBatchPass(const rbl__BatchState *batch, bool sorted, const char *fn, unsigned int *bound)
{
    if (!sorted) { for (int r = 0; r < batch->runCount; r++) rbl__drawBatchQuads(batch, r, batch->runs[r].first, batch->runs[r].count, fn, bound); return; }
    for (int i = 0; i < batch->count; )
    {
        int j = i + 1;
        while ((j < batch->count) && (batch->keys[j].run == batch->keys[i].run)) j++;
        rbl__drawBatchQuads(batch, batch->keys[i].run, i, j - i, fn, bound);
        i = j;
    }
}

typedef struct rbl__BatchLayer { const rbl__BatchState *batch; bool sorted; const char *fn; unsigned int bound; } rbl__BatchLayer;

static void rbl__drawBatchLayer(void *context)
{
    rbl__BatchLayer *layer = (rbl__BatchLayer *)context;
    rbl__drawBatchPass(layer->batch, layer->sorted, layer->fn, &layer->bound);
}

static rbl__Program *rbl__recordVariant(rbl__Program *p);
static rbl__Program *rbl__shadowVariant(rbl__Program *p);
static rbl__Program *rbl__findCaster(unsigned int id);
static rbl__Program *rbl__blendCaster(bool instanced);

// Whether the program every run will draw with has its record variant (compiled here on first need);
// where one cannot be made the batch draws from vertices instead (a shadow pass's casters alike)
static bool rbl__recordVariantsReady(const rbl__BatchState *batch)
{
    for (int r = 0; r < batch->runCount; r++)
    {
        rbl__Program *p = NULL;
        if (rbl__state.shadowPass != NULL) p = rbl__state.shadowPass->state->blending? rbl__blendCaster(false) : rbl__findCaster(rbl__state.casterIds[0]);
        else
        {
            Material m = batch->runs[r].material;
            if (rbl__materialProblem(&m, RBL__PATH_BILLBOARD, &p) != NULL) continue;      // refused at the draw, as ever
            p = rbl__shadowVariant(p);
        }
        if ((p != NULL) && (rbl__recordVariant(p) == NULL)) return false;
        if (rbl__state.shadowPass != NULL) break;          // one caster for every run
    }
    return true;
}

static void rbl__endBatch(RblBatch *pub, const char *fn)
{
    rbl__BatchState *batch = rbl__batchState(pub);
    if ((batch == NULL) || !batch->begun || (batch->pass != rbl__passNow()))
    {
        TraceLog(LOG_WARNING, "RBL: %s: %s", fn, (batch == NULL)? "batch not loaded" : !batch->begun? "no RblBeginBatch in progress" :
                 "the batch began in another pass (shadow map, G-buffer or colour): end it in the pass it began in");
        return;
    }
    batch->begun = false;
    if ((batch->mapped != NULL) && !rbl__unmapBuffer(batch->vboId))
    {
        TraceLog(LOG_WARNING, "RBL: %s: the GPU lost the records of %i billboards (its buffer was unmapped by the system); they are not drawn", fn, batch->count);
        batch->count = 0; batch->runCount = 0;
    }
    batch->mapped = NULL;
    batch->onGpu = batch->onGpu && (batch->count > 0);
    if ((pub->sort < RBL_SORT_NONE) || (pub->sort > RBL_SORT_HYBRID) || !rbl__finite(pub->solidAlpha) || (pub->solidAlpha < 0.0f) || (pub->solidAlpha > 1.0f))
    {
        TraceLog(LOG_WARNING, "RBL: %s: sort mode %i unknown or solidAlpha %g outside 0..1; %i billboards not drawn", fn, pub->sort, pub->solidAlpha, batch->count);
        return;
    }
    int sort = rbl__passSort(pub->sort);
    if (batch->onGpu && ((sort != RBL_SORT_NONE) || (batch->capacity > batch->gpuCapacity))) rbl__recordsToCpu(batch);     // sorting reads them; a new buffer has none
    if (batch->count == 0) return;
    if (batch->capacity > batch->gpuCapacity)
    {
        // Grow the GPU side; on failure keep the old buffers (the batch stays valid) and draw nothing
        rbl__BatchState old = *batch;
        rbl__loadBatchGpu(batch);
        if ((batch->vaoId == 0) || (batch->vboId == 0) || (batch->eboId == 0))
        {
            rbl__unloadBatchGpu(batch);
            batch->vaoId = old.vaoId; batch->vboId = old.vboId; batch->eboId = old.eboId; batch->gpuCapacity = old.gpuCapacity;
            TraceLog(LOG_WARNING, "RBL: %s: GPU buffers for %i billboards could not be created; nothing drawn", fn, batch->capacity);
            return;
        }
        old.fadeVboId = 0;      // the fade and identity buffers are kept (sized below), and the record array
        old.idVboId = 0;
        old.recordVaoId = 0;
        rbl__unloadBatchGpu(&old);
    }
    if (batch->fading && !rbl__reserveStream(&batch->fadeVboId, &batch->fadeGpuCapacity, batch->capacity, RBL__FADE_FLOATS*(int)sizeof(float), fn, "fade")) return;
    if (batch->records && (!rbl__recordVariantsReady(batch) || !rbl__makeRecordArray(batch))) rbl__recordsToVertices(batch);
    const bool idStream = batch->identified && !batch->records;
    if (idStream && !rbl__reserveStream(&batch->idVboId, &batch->idGpuCapacity, batch->capacity, RBL__ID_BYTES, fn, "caster identity")) return;
    if ((sort != RBL_SORT_NONE) && !rbl__sortBatch(batch))
    {
        TraceLog(LOG_WARNING, "RBL: %s: out of memory sorting %i billboards; drawn in submission order", fn, batch->count);
        sort = RBL_SORT_NONE;
    }
    bool sorted = (sort != RBL_SORT_NONE);

    rlDrawRenderBatchActive();      // keep draw order with raylib's own pending geometry
    // Billboards seen from behind are drawn (two-sided, shaded on the side seen): culling goes off for
    // this draw and back on after (raylib's default; rlgl cannot report the caller's state). Shadow
    // passes keep it off throughout.
    bool cullOff = (rbl__state.shadowPass == NULL) && batch->backFacing;
    if (cullOff) rlDisableBackfaceCulling();
    rlEnableVertexArray(batch->vaoId);
    if (batch->fading) rlUpdateVertexBuffer(batch->fadeVboId, sorted? batch->fadeSorted : batch->fade, batch->count*RBL__FADE_FLOATS*(int)sizeof(float), 0);
    if (idStream) rlUpdateVertexBuffer(batch->idVboId, sorted? batch->idsSorted : batch->ids, batch->count*RBL__ID_BYTES, 0);
    if (!batch->onGpu) rlUpdateVertexBuffer(batch->vboId, sorted? batch->sorted : batch->vertices, batch->count*(batch->records? (int)sizeof(rbl__BatchRecord) : 4*(int)sizeof(RblVertex)), 0);
    if (batch->records) rlEnableVertexArray(batch->recordVaoId);
    else rlEnableVertexBufferElement(batch->eboId);
    rbl__BatchLayer layer = { batch, sorted, fn, 0 };
    rbl__drawLayers(sort, pub->solidAlpha, rbl__drawBatchLayer, &layer);
    unsigned int bound = layer.bound;
    if (batch->fading) rlDisableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD2);     // raylib's next draws never see it
    rbl__unbindMaterial(bound);
    rlDisableVertexArray();
    if (cullOff) rlEnableBackfaceCulling();
}

// The immediate path: a one-quad batch (fade NULL for a plain billboard)
static void rbl__drawBillboard(Camera3D camera, Material material, const RblBillboard *billboard, const RblFade *fade, const char *fn)
{
    RblBatch *immediate = &rbl__state.immediate;
    // Everything is checked before the one-quad batch is touched (or created on first use)
    rbl__Program *program = NULL;
    int texW = 1, texH = 1;
    const char *bad = !rbl__cameraOk(camera)? "camera with NaN/Inf or huge fields, fovy outside (0, 180) or unknown projection" :
                      rbl__materialProblem(&material, RBL__PATH_BILLBOARD, &program);
    if (bad == NULL) rbl__albedoSize(&material, &texW, &texH);
    if ((bad == NULL) && !rbl__billboardOk(billboard, texW, texH)) bad = "NaN/Inf or huge input, or bad facing";
    if ((bad == NULL) && (fade != NULL) && !rbl__fadeOk(fade, RBL__BILLBOARD_LIMIT_EXPONENT)) bad = "fade weight outside 0..1, NaN/Inf or huge source, or bad clip";
    const rbl__Polygon *poly = NULL;
    if ((bad == NULL) && (fade == NULL) && !rbl__billboardPolygon(billboard->flags, &poly)) bad = "its RBL_FRAME_POLYGON bits name no loaded atlas's polygon (unloaded atlas?)";
    if ((bad == NULL) && (rbl__slotCount(poly, billboard) > RBL_MAX_BATCH_BILLBOARDS)) bad = "its polygon has more triangle pairs than RBL_MAX_BATCH_BILLBOARDS";
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: %s: %s", fn, bad); return; }
    // One quad slot, or as many as the polygon's (the batch is made that large, without a growth line)
    int slots = (bad == NULL)? rbl__slotCount(poly, billboard) : 1;
    if (slots < 1) slots = 1;
    if ((immediate->state != NULL) && (immediate->state->capacity < slots)) RblUnloadBatch(immediate);
    if (immediate->state == NULL)
    {
        *immediate = RblLoadBatch(slots);     // created on first use, released by RblClose()
        if (!RblIsBatchValid(*immediate)) return;
        immediate->state->vertexOnly = true;    // one quad: records would save nothing
    }
    RblBeginBatch(immediate, camera);
    rbl__batchAdd(immediate->state, &material, billboard, fade, fn);
    rbl__endBatch(immediate, fn);
}

void RblDrawBillboard(Camera3D camera, Material material, RblBillboard billboard) { rbl__drawBillboard(camera, material, &billboard, NULL, "RblDrawBillboard"); }

void RblDrawBillboardFade(Camera3D camera, Material material, RblBillboard billboard, RblFade fade) { rbl__drawBillboard(camera, material, &billboard, &fade, "RblDrawBillboardFade"); }

// After RblClose, the module's tables go with the last object the caller still holds (nothing loaded
// and no lit program left): the next load starts afresh
static void rbl__tidyAfterClose(void)
{
    if (!rbl__state.closed || (rbl__state.programCount > 0)) return;
    for (int i = 0; i < rbl__state.liveCount; i++) if (rbl__state.live[i].id != 0) return;
    for (int i = 0; i < rbl__state.quarantineCount; i++) MemFree(rbl__state.quarantine[i]);
    RBL_FREE(rbl__state.quarantine);
    RBL_FREE(rbl__state.dead);
    RBL_FREE(rbl__state.programs);
    RBL_FREE(rbl__state.live);
    RBL_FREE(rbl__state.polyRanges);
    memset(&rbl__state, 0, sizeof(rbl__state));
}

void RblClose(void)
{
    // The header's own resources go now (GL objects only while a context exists); what the caller
    // holds (batches, instance buffers, G-buffers, shadow maps) stays valid until its own unload, before
    // or after this, before or after CloseWindow
    if (rbl__state.immediate.state != NULL) RblUnloadBatch(&rbl__state.immediate);
    rbl__releaseCapture();
    if ((rbl__state.polyTableId != 0) && rbl__glUsable()) rlUnloadTexture(rbl__state.polyTableId);
    rbl__state.polyTableId = 0;
    RBL_FREE(rbl__state.scene.lights); RBL_FREE(rbl__state.scene.staging); RBL_FREE(rbl__state.scene.lightFeatures);
    rbl__freeLightGrid(&rbl__state.scene.grid);
    memset(&rbl__state.scene, 0, sizeof(rbl__state.scene));
    // Lit programs become their holders' plain raylib Shaders (UnloadShader, UnloadMaterial or
    // RblUnloadLitShader release them later; those raylib already deleted are simply forgotten)
    for (int i = rbl__state.programCount - 1; i >= 0; i--)
        if ((rbl__state.programs[i]->key.kind == RBL__KIND_LIT) && (rbl__state.programs[i]->key.sprites || (rbl__state.programs[i]->shadowBase != NULL)))
        {
            // resident-sprite and receiver variants are the header's
            if (rbl__glUsable()) rlUnloadShaderProgram(rbl__state.programs[i]->shader.id);
            rbl__removeProgram(rbl__state.programs[i]);
            i = rbl__state.programCount;
        }
    for (int i = rbl__state.programCount - 1; i >= 0; i--)
        if (rbl__state.programs[i]->key.kind == RBL__KIND_LIT) rbl__removeProgram(rbl__state.programs[i]);
    for (int i = 0; i < rbl__state.quarantineCount; i++) MemFree(rbl__state.quarantine[i]);
    RBL_FREE(rbl__state.quarantine); RBL_FREE(rbl__state.dead);
    rbl__state.quarantine = NULL; rbl__state.dead = NULL;
    rbl__state.quarantineCount = rbl__state.quarantineCapacity = rbl__state.deadCount = rbl__state.deadCapacity = 0;
    rbl__state.closed = true;
    rbl__tidyAfterClose();
}

//----------------------------------------------------------------------------------
// Module Functions Definition: instanced path   >>instanced
//----------------------------------------------------------------------------------
// Instance attribute locations: above raylib's defaults (0..9), declared in lit_instanced.vs.glsl
#define RBL__INSTANCE_LOCATION 10
#define RBL__INSTANCE_ATTRIBUTES 5      // position, size, source, tint, flags

static void rbl__loadInstanceGpu(rbl__InstanceBufferState *buffer)
{
    const int stride = (int)sizeof(RblInstance);
    buffer->vaoId = rlLoadVertexArray();
    rlEnableVertexArray(buffer->vaoId);
    buffer->vboId = rlLoadVertexBuffer(NULL, buffer->capacity*stride, true);
    const unsigned int loc = RBL__INSTANCE_LOCATION;
    rlSetVertexAttribute(loc + 0, 4, RL_FLOAT, false, stride, (int)offsetof(RblInstance, position));
    rlSetVertexAttribute(loc + 1, 4, RL_FLOAT, false, stride, (int)offsetof(RblInstance, size));
    rlSetVertexAttribute(loc + 2, 4, RL_FLOAT, false, stride, (int)offsetof(RblInstance, source));
    rlSetVertexAttribute(loc + 3, 4, RL_UNSIGNED_BYTE, true, stride, (int)offsetof(RblInstance, tint));
    rlSetVertexAttribute(loc + 4, 1, 0x1405 /* GL_UNSIGNED_INT, converted to float */, false, stride, (int)offsetof(RblInstance, flags));
    for (unsigned int i = 0; i < RBL__INSTANCE_ATTRIBUTES; i++) { rlEnableVertexAttribute(loc + i); rlSetVertexAttributeDivisor(loc + i, 1); }
    rlDisableVertexArray();
}

static void rbl__freeInstanceState(rbl__InstanceBufferState *b)
{
    if (!rbl__glUsable()) b->vaoId = b->vboId = b->fadeVboId = 0;        // gone with the context
    if (b->vaoId != 0) rlUnloadVertexArray(b->vaoId);
    if (b->vboId != 0) rlUnloadVertexBuffer(b->vboId);
    if (b->fadeVboId != 0) rlUnloadVertexBuffer(b->fadeVboId);
    RBL_FREE(b->fadeStaging);
    RBL_FREE(b->staging);
    RBL_FREE(b->sorted);
    RBL_FREE(b->keys);
    RBL_FREE(b);
}

// The state of a loaded instance buffer, or NULL (never dereferences a stale copy's pointer)
static rbl__InstanceBufferState *rbl__instanceState(const RblInstanceBuffer *buffer)
{
    return ((buffer != NULL) && rbl__isLive(buffer->id, buffer->state))? buffer->state : NULL;
}

RblInstanceBuffer RblLoadInstanceBuffer(int capacity)
{
    RblInstanceBuffer buffer;
    memset(&buffer, 0, sizeof(buffer));
    if ((capacity < 0) || (capacity > RBL_MAX_INSTANCES)) { TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: capacity %i outside 0..%i", capacity, RBL_MAX_INSTANCES); return buffer; }
    if (rbl__needsGlsl3("instanced billboards") != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: %s", rbl__state.problem); return buffer; }
    if (capacity == 0) capacity = RBL_BATCH_DEFAULT_CAPACITY;
    rbl__InstanceBufferState *b = (rbl__InstanceBufferState *)RBL_CALLOC(1, sizeof(rbl__InstanceBufferState));
    if (b != NULL) b->staging = (RblInstance *)RBL_MALLOC((size_t)capacity*sizeof(RblInstance));
    if ((b == NULL) || (b->staging == NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: out of memory for %i instances", capacity);
        RBL_FREE(b);
        return buffer;
    }
    b->capacity = capacity;
    rbl__loadInstanceGpu(b);
    unsigned int id = ((b->vaoId != 0) && (b->vboId != 0))? rbl__liveAdd(b) : 0;
    if (id == 0)
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: GPU buffers could not be created (no GL context?)");
        rbl__freeInstanceState(b);
        return buffer;
    }
    buffer.capacity = capacity;
    buffer.state = b;
    buffer.id = id;
    return buffer;
}

bool RblIsInstanceBufferValid(RblInstanceBuffer buffer)
{
    return rbl__instanceState(&buffer) != NULL;
}

void RblUnloadInstanceBuffer(RblInstanceBuffer *buffer)
{
    if (!rbl__unloadable(buffer, (buffer != NULL)? buffer->id : 0, (buffer != NULL)? buffer->state : NULL, "RblUnloadInstanceBuffer", "instance buffer")) { if (buffer != NULL) memset(buffer, 0, sizeof(*buffer)); return; }
    rbl__liveRemove(buffer->id);
    rbl__freeInstanceState(buffer->state);
    memset(buffer, 0, sizeof(*buffer));
    rbl__tidyAfterClose();
}

// The 12 floats (position .. source) hold no NaN, Inf or |value| >= 2^120
static inline bool rbl__instanceOk(const RblInstance *in)
{
    return rbl__exponentsBelow(&in->position, 12, RBL__INSTANCE_LIMIT_EXPONENT);
}

// Instances ordered back to front by their pivots' depth along the view axis, in buffer->sorted;
// NULL when the scratch cannot be allocated
static const RblInstance *rbl__sortInstances(rbl__InstanceBufferState *buffer, Camera3D camera, const RblInstance *in, int n)
{
    void *sorted = buffer->sorted;
    bool reserved = rbl__reserveSort(&sorted, sizeof(RblInstance), &buffer->keys, &buffer->sortCapacity, buffer->capacity);
    buffer->sorted = (RblInstance *)sorted;
    if (!reserved) return NULL;
    RblCameraFrame view = rbl__cameraFrame(camera);
    for (int i = 0; i < n; i++)
    {
        buffer->keys[i].depth = -rbl__dot(rbl__sub(in[i].position, view.eye), view.back);
        buffer->keys[i].index = i;
        buffer->keys[i].run = 0;
    }
    qsort(buffer->keys, (size_t)n, sizeof(rbl__SortKey), rbl__compareKeys);
    for (int i = 0; i < n; i++) buffer->sorted[i] = in[buffer->keys[i].index];
    return buffer->sorted;
}

// Fade attribute locations of lit_instanced.vs.glsl: second source, weight, flags, both clips
#define RBL__FADE_ATTRIBUTES 5
static const unsigned int rbl__fadeLocations[RBL__FADE_ATTRIBUTES] = { 15, 6, 7, 8, 9 };

// The fade buffer of an instanced draw (its VAO bound): fades uploaded and bound per instance, or
// without them the attributes off and constant (weight 0) for a program that reads them
static void rbl__bindInstanceFades(rbl__InstanceBufferState *buffer, const rbl__Program *program, const RblFade *fades, int n)
{
    if (fades == NULL)
    {
        // Off already: a draw with fades turns them off after itself
        if ((program != NULL) && program->key.desc.crossFade)
        {
            const float none[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
            rlSetVertexAttributeDefault((int)rbl__fadeLocations[1], none, SHADER_ATTRIB_FLOAT, 1);
            rlSetVertexAttributeDefault((int)rbl__fadeLocations[3], none, SHADER_ATTRIB_VEC4, 4);     // zero clips: whole quads
            rlSetVertexAttributeDefault((int)rbl__fadeLocations[4], none, SHADER_ATTRIB_VEC4, 4);
        }
        return;
    }
    const int stride = (int)sizeof(RblFade);
    rlUpdateVertexBuffer(buffer->fadeVboId, fades, n*stride, 0);     // binds it for the pointers below
    rlSetVertexAttribute(rbl__fadeLocations[0], 4, RL_FLOAT, false, stride, (int)offsetof(RblFade, source));
    rlSetVertexAttribute(rbl__fadeLocations[1], 1, RL_FLOAT, false, stride, (int)offsetof(RblFade, weight));
    rlSetVertexAttribute(rbl__fadeLocations[2], 1, 0x1405 /* GL_UNSIGNED_INT, converted to float */, false, stride, (int)offsetof(RblFade, flags));
    rlSetVertexAttribute(rbl__fadeLocations[3], 4, RL_FLOAT, false, stride, (int)offsetof(RblFade, clip));
    rlSetVertexAttribute(rbl__fadeLocations[4], 4, RL_FLOAT, false, stride, (int)(offsetof(RblFade, clip) + sizeof(Rectangle)));
    for (int i = 0; i < RBL__FADE_ATTRIBUTES; i++) { rlEnableVertexAttribute(rbl__fadeLocations[i]); rlSetVertexAttributeDivisor(rbl__fadeLocations[i], 1); }
}

// ---- polygon frames on the instanced stage -----------------------------------------------------------
#define RBL__FRAME_TABLE_WIDTH 1024         // Texels per row of a frame or polygon table (rows: at most 2048, ES 3's least texture size)
static rbl__Program *rbl__compileProgram(const rbl__ProgramKey *key);
static void rbl__bindSceneTints(const rbl__Program *p);
static void rbl__bindSoftDepth(const rbl__Program *p, const Material *material);
static void rbl__casterDepth(const rbl__Program *caster);

// A header-owned variant of p: p's key with rbl__ProgramKey.sprites bit `bit`, compiled on first
// need and held in *slot until p goes; NULL (problem set) on failure
static rbl__Program *rbl__ownVariant(rbl__Program *p, rbl__Program **slot, int bit)
{
    if (*slot != NULL) return *slot;
    rbl__ProgramKey key = p->key;
    key.sprites |= bit;
    *slot = rbl__compileProgram(&key);
    return *slot;
}

// The polygon-frame variant (RBL_POLYGONS) of an instanced program (plain or resident-sprite): draws
// without polygons never compile it
static rbl__Program *rbl__polygonVariant(rbl__Program *p) { return rbl__ownVariant(p, &p->polygonVariant, 2); }

// The batch-record variant of a vertex-buffer program (lit, G-buffer geometry or caster): its
// fragment stage behind the instanced vertex stage's RBL_BATCH_RECORD
static rbl__Program *rbl__recordVariant(rbl__Program *p) { return rbl__ownVariant(p, &p->recordVariant, 4); }

// A polygon's corners for the instanced stage (cut along diagonal d), 3 per triangle from its slots,
// each pair (a, b) of frame fractions, two corners a texel (RGBA32F); returns the texels written
static int rbl__polygonCorners(const rbl__Polygon *poly, int d, float *out)
{
    int k = 0;
    for (int sl = 0; sl < poly->slotCount[d]; sl++)
    {
        const unsigned int *v = poly->slots[d] + 4*sl;
        const unsigned int tri[6] = { v[0], v[1], v[2], v[0], v[2], v[3] };
        for (int c = 0; c < ((v[2] == v[3])? 3 : 6); c++, k++) { out[2*k] = poly->frac[tri[c]].x; out[2*k + 1] = poly->frac[tri[c]].y; }
    }
    if (k & 1) { out[2*k] = out[2*k + 1] = 0.0f; }
    return (k + 1)/2;
}

// The texels of a polygon's corners, both diagonals' (rbl__polygonCorners)
static inline size_t rbl__polygonTexels(const rbl__Polygon *poly) { return (size_t)(3*poly->triangles[0] + 1)/2 + (size_t)(3*poly->triangles[1] + 1)/2 + (size_t)(3*poly->triangles[2] + 1)/2; }

// The most corners of a polygon's two cuts
static inline int rbl__polygonMaxCorners(const rbl__Polygon *poly)
{
    int t = (poly->triangles[0] > poly->triangles[1])? poly->triangles[0] : poly->triangles[1];
    return 3*((poly->triangles[2] > t)? poly->triangles[2] : t);
}

// The header's polygon table for instanced draws, rebuilt when atlases came or went since: texels
// 2(h - base) and 2(h - base) + 1 hold handle h's first corner texel and corner count for each cut,
// then the corners (rbl__polygonCorners). false (problem set) when it cannot be made
static bool rbl__polygonTable(void)
{
    if ((rbl__state.polyTableId != 0) && (rbl__state.polyTableVersion == rbl__state.polyVersion)) return true;
    if (rbl__state.polyTableId != 0) { rlUnloadTexture(rbl__state.polyTableId); rbl__state.polyTableId = 0; }
    if (rbl__state.polyRangeCount == 0) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "no polygons loaded"); return false; }
    unsigned int base = rbl__state.polyRanges[0].first;
    const rbl__PolyRange *last = &rbl__state.polyRanges[rbl__state.polyRangeCount - 1];
    size_t texels = 2*(size_t)(last->first + (unsigned int)last->count - base);
    for (int r = 0; r < rbl__state.polyRangeCount; r++)
        for (int i = 0; i < rbl__state.polyRanges[r].count; i++) texels += rbl__polygonTexels(&rbl__state.polyRanges[r].polygons[i]);
    size_t rows = (texels + RBL__FRAME_TABLE_WIDTH - 1)/RBL__FRAME_TABLE_WIDTH;
    if (rows > 2048) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "the loaded atlases' polygons need %zu texels, more than 1024 x 2048", texels); return false; }
    float *table = (float *)RBL_CALLOC(rows*RBL__FRAME_TABLE_WIDTH*4, sizeof(float));
    if (table == NULL) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "out of memory for the polygon table"); return false; }
    size_t at = 2*(size_t)(last->first + (unsigned int)last->count - base);
    for (int r = 0; r < rbl__state.polyRangeCount; r++)
        for (int i = 0; i < rbl__state.polyRanges[r].count; i++)
        {
            const rbl__Polygon *poly = &rbl__state.polyRanges[r].polygons[i];
            float *h = table + 8*(size_t)(rbl__state.polyRanges[r].first + (unsigned int)i - base);
            for (int d = 0; d < 3; d++)
            {
                h[2*d] = (float)at; h[2*d + 1] = (float)(3*poly->triangles[d]);
                at += (size_t)rbl__polygonCorners(poly, d, table + 4*at);
            }
        }
    rbl__state.polyTableId = rlLoadTexture(table, RBL__FRAME_TABLE_WIDTH, (int)rows, RL_PIXELFORMAT_UNCOMPRESSED_R32G32B32A32, 1);
    RBL_FREE(table);
    if (rbl__state.polyTableId == 0) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "polygon table texture could not be created"); return false; }
    rlTextureParameters(rbl__state.polyTableId, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
    rlTextureParameters(rbl__state.polyTableId, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
    rbl__state.polyTableVersion = rbl__state.polyVersion;
    rbl__state.polyTableBase = base;
    return true;
}

// An instance's polygon bits: none, or a loaded polygon (its corners raise *corners); false when they
// name none
static inline bool rbl__instancePolygonOk(const RblInstance *in, int *corners)
{
    unsigned int h = rbl__polygonHandle(in->flags);
    if (h == 0u) return true;
    const rbl__Polygon *poly = rbl__polygonAt(h);
    if (poly == NULL) return false;
    if (rbl__polygonMaxCorners(poly) > *corners) *corners = rbl__polygonMaxCorners(poly);
    return true;
}

// The draw's instances that pass its checks (rbl__instanceOk; a polygon handle of a loaded atlas,
// *corners raised to its most corners), copied in order into out (the mapped GPU buffer) with the bad
// ones left out: each read once, written once, never read back. *back: whether the camera sees the
// back of a kept one (backMode and n from rbl__backMode; NEVER: not looked for). Returns how many
static int rbl__copyInstances(const RblInstance *in, int count, unsigned char *out, const RblCameraFrame *view, int backMode, Vector3 backNormal, int *corners, bool *back)
{
    int kept = 0, i = 0;
    bool seekBack = (backMode != RBL__BACK_NEVER);
#if defined(RBL__SSE2)
    // Four at a time where the back test (if still looked for) fits four lanes: rbl__backAt's PLANE
    // sums in its order; a four holding a bad instance goes one at a time
    const __m128i expBits = _mm_set1_epi32(0x7f800000), bias = _mm_set1_epi32((int)((256u - RBL__INSTANCE_LIMIT_EXPONENT) << 23));
    const __m128 zero = _mm_setzero_ps(), eyeX = _mm_set1_ps(view->eye.x), eyeY = _mm_set1_ps(view->eye.y), eyeZ = _mm_set1_ps(view->eye.z),
                 normalX = _mm_set1_ps(backNormal.x), normalY = _mm_set1_ps(backNormal.y), normalZ = _mm_set1_ps(backNormal.z);
    const bool laneBack = (backMode == RBL__BACK_PLANE) || (backMode == RBL__BACK_ALWAYS);
    int single = 0;         // instances of a four that failed a check, left to take one at a time
#endif
    while (i < count)
    {
#if defined(RBL__SSE2)
        if ((single == 0) && (i + 4 <= count) && (!seekBack || laneBack))
        {
            const unsigned char *p = (const unsigned char *)(in + i);
            unsigned char *o = out + (size_t)kept*sizeof(RblInstance);
            for (int line = 0; line < 4*(int)sizeof(RblInstance); line += 64)
            {
                _mm_prefetch((const char *)(p + RBL__STRETCH_AHEAD + line), _MM_HINT_T0);
                _mm_prefetch((const char *)(o + RBL__STRETCH_AHEAD + line), _MM_HINT_T0);
            }
            __m128i carry = _mm_setzero_si128();
            __m128 pivot[4];
            unsigned int polygon = 0u;
            for (int l = 0; l < 4; l++)
            {
                const unsigned char *q = p + (size_t)l*sizeof(RblInstance);
                const __m128i v0 = _mm_loadu_si128((const __m128i *)(const void *)q), v1 = _mm_loadu_si128((const __m128i *)(const void *)(q + 16)),
                              v2 = _mm_loadu_si128((const __m128i *)(const void *)(q + 32)), v3 = _mm_loadl_epi64((const __m128i *)(const void *)(q + 48));
                unsigned int flags;
                memcpy(&flags, q + offsetof(RblInstance, flags), sizeof(flags));
                carry = _mm_or_si128(carry, _mm_or_si128(_mm_add_epi32(_mm_and_si128(v0, expBits), bias),
                                                         _mm_or_si128(_mm_add_epi32(_mm_and_si128(v1, expBits), bias), _mm_add_epi32(_mm_and_si128(v2, expBits), bias))));
                polygon |= rbl__polygonHandle(flags);
                pivot[l] = _mm_castsi128_ps(v0);
                _mm_storeu_si128((__m128i *)(void *)(o + (size_t)l*sizeof(RblInstance)), v0);
                _mm_storeu_si128((__m128i *)(void *)(o + (size_t)l*sizeof(RblInstance) + 16), v1);
                _mm_storeu_si128((__m128i *)(void *)(o + (size_t)l*sizeof(RblInstance) + 32), v2);
                _mm_storel_epi64((__m128i *)(void *)(o + (size_t)l*sizeof(RblInstance) + 48), v3);
            }
            bool ok = (_mm_movemask_ps(_mm_castsi128_ps(carry)) == 0);
            for (int l = 0; ok && (polygon != 0u) && (l < 4); l++) ok = rbl__instancePolygonOk(&in[i + l], corners);
            if (ok)
            {
                if (seekBack)
                {
                    _MM_TRANSPOSE4_PS(pivot[0], pivot[1], pivot[2], pivot[3]);     // lanes: x, y, z, rotation
                    const __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(normalX, _mm_sub_ps(eyeX, pivot[0])), _mm_mul_ps(normalY, _mm_sub_ps(eyeY, pivot[1]))),
                                                _mm_mul_ps(normalZ, _mm_sub_ps(eyeZ, pivot[2])));
                    if ((backMode == RBL__BACK_ALWAYS) || (_mm_movemask_ps(_mm_cmplt_ps(d, zero)) != 0)) { *back = true; seekBack = false; }
                }
                kept += 4;
                i += 4;
                continue;
            }
            single = 4;         // this four one at a time (the slots written are written again)
        }
        if (single > 0) single--;
#endif
        if (rbl__instanceOk(&in[i]) && rbl__instancePolygonOk(&in[i], corners))
        {
            memcpy(out + (size_t)kept*sizeof(RblInstance), &in[i], sizeof(RblInstance));
            kept++;
            if (seekBack && rbl__backAt(view, backMode, backNormal, in[i].position)) { *back = true; seekBack = false; }
        }
        i++;
    }
    return kept;
}

// The per-draw frame of the instanced stage, rblInstancing[7] (layout in lit_instanced.vs.glsl); the
// resident-sprite variant's [7] (frame[28..31]) zero here, set by its draw
static void rbl__instancingFrame(const RblInstancedDesc *desc, const RblCameraFrame *view, int texW, int texH, float frame[32])
{
    const float f[32] = {
        view->eye.x, view->eye.y, view->eye.z, (float)(rbl__castFacing(&rbl__state.cast, desc->facing) + (rbl__state.cast.faceLight? 8 : 0)),
        view->right.x, view->right.y, view->right.z, desc->roundness,
        view->up.x, view->up.y, view->up.z, (float)texW,
        view->back.x, view->back.y, view->back.z, (float)texH,
        desc->up.x, desc->up.y, desc->up.z, rbl__state.cast.minSin,
        desc->axis.x, desc->axis.y, desc->axis.z, view->orthographic? 1.0f : 0.0f,
        rbl__state.cast.light.x, rbl__state.cast.light.y, rbl__state.cast.light.z, rbl__state.cast.light.w, 0.0f, 0.0f, 0.0f, 0.0f };
    memcpy(frame, f, sizeof(f));
}

// An instanced draw's desc (facing, sort, finite directions; a CAMERA_PLANE up below 2^30), its
// directions tamed as the CPU tames them (FIXED up and normal, AXIS axis: long ones scaled)
static bool rbl__instancedDescOk(RblInstancedDesc *desc)
{
    if ((desc->facing < RBL_FACING_CAMERA_PLANE) || (desc->facing > RBL_FACING_FIXED) || !rbl__finite3(desc->up) ||
        !rbl__finite3(desc->axis) || !rbl__finite(desc->roundness) || (desc->sort < RBL_SORT_NONE) || (desc->sort > RBL_SORT_HYBRID) ||
        ((desc->facing == RBL_FACING_CAMERA_PLANE) && !rbl__exponentsBelow(&desc->up, 3, RBL__UP_LIMIT_EXPONENT))) return false;
    if (desc->facing != RBL_FACING_CAMERA_PLANE) desc->up = rbl__tame(desc->up);
    desc->axis = rbl__tame(desc->axis);
    return true;
}

typedef struct rbl__InstanceLayer { rbl__Program *program; const Material *material; int count, vertices; } rbl__InstanceLayer;   // vertices: 6, or a polygon draw's corners

static void rbl__drawInstanceLayer(void *context)
{
    const rbl__InstanceLayer *layer = (const rbl__InstanceLayer *)context;
    rbl__applyMaterialValues(layer->program, layer->material);
    rlDrawVertexArrayInstanced(0, layer->vertices, layer->count);
}

int RblDrawInstanced(RblInstanceBuffer *pub, Camera3D camera, Material material, RblInstancedDesc desc, const RblInstance *instances, int count)
{
    rbl__InstanceBufferState *buffer = rbl__instanceState(pub);
    if (buffer == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: instance buffer not loaded"); return 0; }
    if (!rbl__cameraOk(camera)) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: camera with NaN/Inf or huge fields, fovy outside (0, 180) or unknown projection"); return 0; }
    if ((count < 0) || (count > RBL_MAX_INSTANCES) || ((count > 0) && (instances == NULL))) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: bad instance array (count %i, limit %i)", count, RBL_MAX_INSTANCES); return 0; }
    if (!rbl__instancedDescOk(&desc))
    {
        TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: bad RblInstancedDesc (facing %i, sort %i, NaN/Inf vectors or a CAMERA_PLANE up of length >= 2^30)", desc.facing, desc.sort);
        return 0;
    }
    rbl__Program *checked = NULL;
    const char *bad = rbl__materialProblem(&material, RBL__PATH_INSTANCED, &checked);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: %s", bad); return 0; }
    if (count > buffer->capacity)
    {
        int newCapacity = buffer->capacity;
        while (newCapacity < count) newCapacity = (newCapacity > RBL_MAX_INSTANCES/2)? RBL_MAX_INSTANCES : newCapacity*2;
        RblInstance *staging = (RblInstance *)RBL_REALLOC(buffer->staging, (size_t)newCapacity*sizeof(RblInstance));
        if (staging == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: out of memory for %i instances", newCapacity); return 0; }
        buffer->staging = staging;
        const unsigned int oldVao = buffer->vaoId, oldVbo = buffer->vboId;
        const int oldCapacity = buffer->capacity;
        buffer->capacity = newCapacity;
        rbl__loadInstanceGpu(buffer);
        if ((buffer->vaoId == 0) || (buffer->vboId == 0))
        {
            // Keep the old GPU buffers: the object stays valid at its old capacity
            if (buffer->vaoId != 0) rlUnloadVertexArray(buffer->vaoId);
            if (buffer->vboId != 0) rlUnloadVertexBuffer(buffer->vboId);
            buffer->vaoId = oldVao; buffer->vboId = oldVbo; buffer->capacity = oldCapacity;
            TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: GPU buffer for %i instances could not be created", newCapacity);
            return 0;
        }
        rlUnloadVertexArray(oldVao);
        rlUnloadVertexBuffer(oldVbo);
        TraceLog(LOG_INFO, "RBL: instance buffer grown from %i to %i (reserve more in RblLoadInstanceBuffer)", oldCapacity, newCapacity);
        pub->capacity = newCapacity;
    }

    // Validate in place, so no NaN reaches the GPU buffer: a clean set is uploaded straight from the
    // caller's array (the per-instance CPU cost is this read), one with bad instances is compacted
    // into the staging copy first
    // A fade travels with its instance: a bad one skips both (the fades are compacted alongside)
    const RblFade *fades = desc.fades;
    if ((fades != NULL) && (buffer->fadeStagingCapacity < buffer->capacity))
    {
        RblFade *f = (RblFade *)RBL_MALLOC((size_t)buffer->capacity*2*sizeof(RblFade));     // compacted, then sorted
        if (f == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: out of memory for %i fades", buffer->capacity); return 0; }
        RBL_FREE(buffer->fadeStaging);
        buffer->fadeStaging = f;
        buffer->fadeStagingCapacity = buffer->capacity;
    }
    // Polygon frames: the most corners one instance needs (0: quads only; with fades every instance is its quad)
    int corners = 0;
    int *cornersAt = (fades == NULL)? &corners : NULL;
    int n = 0;
    // Where the context maps buffers and the draw keeps the array's order without fades, the checks
    // copy each kept instance straight into the GPU buffer (nothing uploaded below); contents lost at
    // the unmap (the system's), or no mapping: the checks and upload below
    bool mappedUpload = false, mappedBack = false;
    if ((count > 0) && (fades == NULL) && (rbl__passSort(desc.sort) == RBL_SORT_NONE) && !RBL__HOOK(instanceNoMap) && rbl__canMap())
    {
        const RblCameraFrame seen = rbl__cameraFrame(camera);
        Vector3 backNormal = { 0.0f, 0.0f, 0.0f };
        const int backMode = (rbl__state.shadowPass == NULL)? rbl__backMode(&seen, desc.facing, desc.up, desc.axis, &backNormal) : RBL__BACK_NEVER;
        unsigned char *out = (unsigned char *)rbl__mapBuffer(buffer->vboId, (size_t)count*sizeof(RblInstance), false);
        if (out != NULL)
        {
            n = rbl__copyInstances(instances, count, out, &seen, backMode, backNormal, &corners, &mappedBack);
            mappedUpload = rbl__unmapBuffer(buffer->vboId);
            if (!mappedUpload) { n = 0; corners = 0; mappedBack = false; }
        }
    }
    if (mappedUpload)
    {
        pub->skipped = count - n;
        if (n < count) TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: %i instance(s) skipped (NaN/Inf or |value| >= 2^120 = 1.3e36, a fade weight outside 0..1, or RBL_FRAME_POLYGON bits of no loaded atlas)", pub->skipped);
    }
    while (!mappedUpload && (n < count) && rbl__instanceOk(&instances[n]) && ((fades == NULL) || rbl__fadeOk(&fades[n], RBL__INSTANCE_LIMIT_EXPONENT)) &&
           ((cornersAt == NULL) || rbl__instancePolygonOk(&instances[n], cornersAt))) n++;
    const RblInstance *upload = instances;
    const RblFade *fadeUpload = fades;
    if (!mappedUpload) pub->skipped = 0;
    if (!mappedUpload && (n < count))
    {
        memcpy(buffer->staging, instances, (size_t)n*sizeof(RblInstance));
        if (fades != NULL) memcpy(buffer->fadeStaging, fades, (size_t)n*sizeof(RblFade));
        for (int i = n; i < count; i++)
        {
            if (rbl__instanceOk(&instances[i]) && ((fades == NULL) || rbl__fadeOk(&fades[i], RBL__INSTANCE_LIMIT_EXPONENT)) &&
                ((cornersAt == NULL) || rbl__instancePolygonOk(&instances[i], cornersAt)))
            {
                if (fades != NULL) buffer->fadeStaging[n] = fades[i];
                buffer->staging[n++] = instances[i];
            }
            else pub->skipped++;
        }
        upload = buffer->staging;
        if (fades != NULL) fadeUpload = buffer->fadeStaging;
        TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: %i instance(s) skipped (NaN/Inf or |value| >= 2^120 = 1.3e36, a fade weight outside 0..1, or RBL_FRAME_POLYGON bits of no loaded atlas)", pub->skipped);
    }
    if (n == 0) return 0;

    MaterialMap casterMaps[RBL__CASTER_MAPS];
    rbl__Program *program = NULL;
    if (!rbl__prepareDraw(&material, casterMaps, RBL__PATH_INSTANCED, fades != NULL, false, "RblDrawInstanced", &program)) return 0;
    if (corners > 0)
    {
        // Polygon frames: the program's polygon variant, each instance drawn with the draw's most
        // corners (a quad's 6 at least; the rest collapse to one point outside the view)
        rbl__Program *variant = program->key.desc.crossFade? NULL : rbl__polygonVariant(program);
        if ((variant == NULL) && program->key.desc.crossFade) corners = 0;      // cross-fade programs draw quads (the union of two frames)
        else if ((variant == NULL) || !rbl__polygonTable()) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: polygon frames cannot be drawn (%s)", rbl__state.problem); return 0; }
        else
        {
            program = variant;
            material.shader = variant->shader;
            if (rbl__state.shadowPass != NULL) rbl__casterDepth(variant);
            else
            {
                if (variant->key.desc.softParticles) rbl__bindSoftDepth(variant, &material);
                if (variant->key.desc.shadowTransmittance) rbl__bindSceneTints(variant);
            }
            if (corners < 6) corners = 6;
        }
    }
    if ((fades != NULL) && !rbl__reserveStream(&buffer->fadeVboId, &buffer->fadeGpuCapacity, buffer->capacity, (int)sizeof(RblFade), "RblDrawInstanced", "fade")) return 0;
    int sort = rbl__passSort(desc.sort);        // back to front by pivot depth where colour blends
    if (sort != RBL_SORT_NONE)
    {
        const RblInstance *ordered = rbl__sortInstances(buffer, camera, upload, n);
        if (ordered == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: out of memory sorting %i instances; drawn in array order", n); sort = RBL_SORT_NONE; }
        else
        {
            upload = ordered;
            if (fadeUpload != NULL)
            {
                // The keys index the validated set: its fades in the same order, into the second half
                RblFade *sortedFades = buffer->fadeStaging + buffer->fadeStagingCapacity;
                for (int i = 0; i < n; i++) sortedFades[i] = fadeUpload[buffer->keys[i].index];
                fadeUpload = sortedFades;
            }
        }
    }

    int texW, texH;
    rbl__albedoSize(&material, &texW, &texH);
    if ((texW <= 0) || (texH <= 0)) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: albedo texture size %ix%i", texW, texH); return 0; }

    // The per-draw frame in one vec4[7] upload (layout documented in lit_instanced.vs.glsl)
    RblCameraFrame view = rbl__cameraFrame(camera);
    if (rbl__state.shadowPass != NULL) rbl__shadowPassView(&view);
    float frame[32];
    rbl__instancingFrame(&desc, &view, texW, texH, frame);
    // Quads seen from behind are drawn, as in the batch: culling off for this draw only
    bool cullOff = (rbl__state.shadowPass == NULL) && (mappedUpload? mappedBack : rbl__showsBack(&view, desc.facing, desc.up, desc.axis, &upload[0].position, n, sizeof(RblInstance)));
    rlDrawRenderBatchActive();
    unsigned int bound = rbl__bindMaterial(&material);
    rlSetUniform(program->loc[RBL__U_INSTANCING], frame, SHADER_UNIFORM_VEC4, 7);
    const int vertices = (corners > 0)? corners : 6;
    if (corners > 0)
    {
        const float poly[4] = { (float)corners, (float)RBL__FRAME_TABLE_WIDTH, (float)rbl__state.polyTableBase, 0.0f };
        int unit = RBL_FRAME_TABLE_TEXTURE_UNIT;
        rlSetUniform(program->loc[RBL__U_POLYGON], poly, SHADER_UNIFORM_VEC4, 1);
        rlActiveTextureSlot(unit);
        rlEnableTexture(rbl__state.polyTableId);
        rlSetUniform(program->loc[RBL__U_POLYGON_TABLE], &unit, SHADER_UNIFORM_INT, 1);
    }

    if (cullOff) rlDisableBackfaceCulling();
    rlEnableVertexArray(buffer->vaoId);
    rbl__bindInstanceFades(buffer, program, fadeUpload, n);
    if (!mappedUpload) rlUpdateVertexBuffer(buffer->vboId, upload, n*(int)sizeof(RblInstance), 0);
    rbl__InstanceLayer layer = { program, &material, n, vertices };
    rbl__drawLayers(sort, 0.0f, rbl__drawInstanceLayer, &layer);     // hybrid: solid alpha 1, as a batch's default
    if (corners > 0) { rlActiveTextureSlot(RBL_FRAME_TABLE_TEXTURE_UNIT); rlDisableTexture(); }
    rbl__markDrawn(program);
    if (fadeUpload != NULL) for (int i = 0; i < RBL__FADE_ATTRIBUTES; i++) rlDisableVertexAttribute(rbl__fadeLocations[i]);
    rlDisableVertexArray();
    if (cullOff) rlEnableBackfaceCulling();
    rbl__unbindMaterial(bound);
    return n;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: material maps   >>maps
//----------------------------------------------------------------------------------
// Normal decoding, exactly what the shaders compute (GLSL mirror; t = the sampled texel, each
// channel in [0,1] = byte/255, then e = t*2 - 1):
//   RBL_NORMAL_HEMIOCT  e = t.rg*2.0 - 1.0;  p = vec2(e.x + e.y, e.x - e.y)*0.5;
//                       n = normalize(vec3(p, 1.0 - max(abs(e.x), abs(e.y))));
//                       (1 - max(|e.x|,|e.y|) is 1 - |p.x| - |p.y| written so that float rounding cannot
//                       make it negative; z >= 0 and |n| >= 1/sqrt(3) before normalising: never a zero
//                       vector, even between filtered texels)
//   RBL_NORMAL_XY       e = t.rg*2.0 - 1.0;  n = normalize(vec3(e, sqrt(max(0.0, 1.0 - dot(e, e)))));
//                       (|vec3| >= 1 whenever dot(e,e) >= 1, else exactly 1: never zero)
//   RBL_NORMAL_RGB      e = t.rgb*2.0 - 1.0; n = (dot(e, e) < 1.0/4096.0)? vec3(0.0, 0.0, 1.0) : normalize(e);
//                       (a vector shorter than 1/64 is quantisation noise around zero, e.g. the
//                       "no normal" grey 128,128,128 = (1,1,1)/255: it means the flat normal)
//   RBL_NORMAL_NONE     n = vec3(0.0, 0.0, 1.0) (nothing sampled: the geometry normal)
// The same guard (|e|^2 < 1/4096 -> flat) is applied to every decode here, so none can return NaN.
#define RBL__NORMAL_MIN_LEN2    (1.0f/4096.0f)  // Shorter decoded vectors are the flat normal
#define RBL__SPECULAR_DEFAULT   128             // Absent specular: 0.5 (128/255 = 0.502)
#define RBL__OCCLUSION_DEFAULT  255             // Absent occlusion: 1.0 (fully open)

static inline Vector3 rbl__flatNormal(void) { return rbl__v3(0.0f, 0.0f, 1.0f); }

// Channel byte -> [-1,1] as the GPU sees it (t = c/255, then t*2 - 1)
static inline float rbl__snorm(unsigned char c) { return (float)c/255.0f*2.0f - 1.0f; }

// [0,1] -> byte, rounded to nearest and clamped (NaN -> 0)
static inline unsigned char rbl__unorm8(double v)
{
    if (!(v > 0.0)) return 0;
    if (v >= 1.0) return 255;
    return (unsigned char)(v*255.0 + 0.5);
}

// Decoded vector -> unit normal; too short (or NaN) -> flat
static inline Vector3 rbl__decodedUnit(float x, float y, float z)
{
    float l2 = x*x + y*y + z*z;
    if (!(l2 >= RBL__NORMAL_MIN_LEN2) || !rbl__finite(l2)) return rbl__flatNormal();
    float inv = 1.0f/sqrtf(l2);
    return rbl__v3(x*inv, y*inv, z*inv);
}

static inline Vector3 rbl__decodeHemiOct(unsigned char r, unsigned char g)
{
    float ex = rbl__snorm(r), ey = rbl__snorm(g);
    float ax = fabsf(ex), ay = fabsf(ey);
    return rbl__decodedUnit((ex + ey)*0.5f, (ex - ey)*0.5f, 1.0f - ((ax > ay)? ax : ay));
}

static inline Vector3 rbl__decodeXY(unsigned char r, unsigned char g)
{
    float ex = rbl__snorm(r), ey = rbl__snorm(g);
    float z2 = 1.0f - ex*ex - ey*ey;
    return rbl__decodedUnit(ex, ey, (z2 > 0.0f)? sqrtf(z2) : 0.0f);
}

static inline Vector3 rbl__decodeRGB(unsigned char r, unsigned char g, unsigned char b)
{
    return rbl__decodedUnit(rbl__snorm(r), rbl__snorm(g), rbl__snorm(b));
}

static inline Vector3 rbl__decode(const unsigned char c[3], int encoding)
{
    switch (encoding)
    {
        case RBL_NORMAL_HEMIOCT: return rbl__decodeHemiOct(c[0], c[1]);
        case RBL_NORMAL_XY: return rbl__decodeXY(c[0], c[1]);
        case RBL_NORMAL_RGB: return rbl__decodeRGB(c[0], c[1], c[2]);
        default: return rbl__flatNormal();
    }
}

// Input normal -> unit double vector in the z >= 0 hemisphere: z < 0 clamps to 0, any length is
// normalised, zero length / NaN / Inf -> flat (0,0,1)
static void rbl__sanitizeNormal(Vector3 n, double a[3])
{
    double x = n.x, y = n.y, z = (n.z > 0.0f)? n.z : 0.0;
    double l = sqrt(x*x + y*y + z*z);
    if (!rbl__finite3(n) || !(l > 0.0) || (l - l != 0.0)) { a[0] = 0.0; a[1] = 0.0; a[2] = 1.0; return; }
    double inv = 1.0/l;
    a[0] = x*inv; a[1] = y*inv; a[2] = z*inv;
}

// Angular error of a decoded normal d against the unit reference a, as a fraction num/den that is
// monotone in the angle: sin^2 = |a x d|^2/|d|^2 below 90 degrees (precise for small angles, unlike
// 1 - cos), 2 - sin^2 beyond (never reached by hemisphere codes, kept for completeness)
typedef struct rbl__AngleRank { double num, den; } rbl__AngleRank;

static inline rbl__AngleRank rbl__angleRank(const double a[3], Vector3 d)
{
    double dx = d.x, dy = d.y, dz = d.z;
    double cx = a[1]*dz - a[2]*dy, cy = a[2]*dx - a[0]*dz, cz = a[0]*dy - a[1]*dx;
    rbl__AngleRank r;
    r.num = cx*cx + cy*cy + cz*cz;
    r.den = dx*dx + dy*dy + dz*dz;
    if (a[0]*dx + a[1]*dy + a[2]*dz <= 0.0) r.num = 2.0*r.den - r.num;
    return r;
}

static inline bool rbl__angleLess(rbl__AngleRank x, rbl__AngleRank y) { return x.num*y.den < y.num*x.den; }

static inline unsigned char rbl__quantizeSnorm(double e)    // [-1,1] -> byte, rounded
{
    return rbl__unorm8(e*0.5 + 0.5);
}

// Hemi-octahedral, precise: of the floor/ceil neighbours of both coordinates (4 codes), the one whose
// decoded normal is nearest to a. Ranked with the exact (double) decode d: with e the code's [-1,1]
// pair, a.d = e.x*(a.x+a.y)/2 + e.y*(a.x-a.y)/2 + a.z*d.z and |d|^2 = (e.x^2+e.y^2)/2 + d.z^2, the
// largest signed cos^2 = (a.d)|a.d|/|d|^2 wins (compared by cross-multiplying; double keeps ~1e-10
// relative resolution of the squared angle). A winner other than the rounded code is then confirmed
// against it with the float decode the shaders use, so the result is never worse than rounding as
// RblDecodeNormal sees it.
static void rbl__encodeHemiOct(const double a[3], unsigned char out[2])
{
    double s = fabs(a[0]) + fabs(a[1]) + a[2];      // >= 1 for a unit vector (L1 >= L2)
    double px = a[0]/s, py = a[1]/s;
    double fu = ((px + py)*0.5 + 0.5)*255.0, fv = ((px - py)*0.5 + 0.5)*255.0;
    fu = (fu > 0.0)? ((fu < 255.0)? fu : 255.0) : 0.0;      // also maps NaN to 0
    fv = (fv > 0.0)? ((fv < 255.0)? fv : 255.0) : 0.0;
    const int u0 = (int)fu, v0 = (int)fv;                   // floor: non-negative
    const int u1 = (u0 < 255)? u0 + 1 : 255, v1 = (v0 < 255)? v0 + 1 : 255;
    const int ru = (int)(fu + 0.5), rv = (int)(fv + 0.5);   // rounded
    const double p = (a[0] + a[1])*0.5, q = (a[0] - a[1])*0.5;
    double num[4], den[4];
    for (int k = 0; k < 4; k++)
    {
        double ex = ((k & 1)? u1 : u0)*(2.0/255.0) - 1.0, ey = ((k & 2)? v1 : v0)*(2.0/255.0) - 1.0;
        double ax = (ex < 0.0)? -ex : ex, ay = (ey < 0.0)? -ey : ey;
        double dz = 1.0 - ((ax > ay)? ax : ay);
        double dot = ex*p + ey*q + a[2]*dz;
        num[k] = dot*((dot < 0.0)? -dot : dot);
        den[k] = 0.5*(ex*ex + ey*ey) + dz*dz;
    }
    const int rk = ((ru == u1)? 1 : 0) + ((rv == v1)? 2 : 0);
    int best = rk;
    for (int k = 0; k < 4; k++) if (num[k]*den[best] > num[best]*den[k]) best = k;
    int bu = (best & 1)? u1 : u0, bv = (best & 2)? v1 : v0;
    if (best != rk)
    {
        rbl__AngleRank eb = rbl__angleRank(a, rbl__decodeHemiOct((unsigned char)bu, (unsigned char)bv));
        rbl__AngleRank er = rbl__angleRank(a, rbl__decodeHemiOct((unsigned char)ru, (unsigned char)rv));
        if (!rbl__angleLess(eb, er)) { bu = ru; bv = rv; }
    }
    out[0] = (unsigned char)bu;
    out[1] = (unsigned char)bv;
}

// Encode a sanitised unit normal; out[2] is 0 for the two-channel encodings
static void rbl__encode(const double a[3], int encoding, unsigned char out[3])
{
    out[0] = out[1] = out[2] = 0;
    switch (encoding)
    {
        case RBL_NORMAL_HEMIOCT: rbl__encodeHemiOct(a, out); break;
        case RBL_NORMAL_XY: out[0] = rbl__quantizeSnorm(a[0]); out[1] = rbl__quantizeSnorm(a[1]); break;
        case RBL_NORMAL_RGB:
            out[0] = rbl__quantizeSnorm(a[0]); out[1] = rbl__quantizeSnorm(a[1]); out[2] = rbl__quantizeSnorm(a[2]);
            break;
        default: break;
    }
}

static inline bool rbl__knownEncoding(int encoding) { return (encoding == RBL_NORMAL_HEMIOCT) || (encoding == RBL_NORMAL_XY) || (encoding == RBL_NORMAL_RGB); }

void RblEncodeNormal(Vector3 normal, int encoding, unsigned char out[3])
{
    const double x = normal.x, y = normal.y, z = normal.z;
    const char *bad = (out == NULL)? "NULL out" : !rbl__knownEncoding(encoding)? "encoding is not HEMIOCT, XY or RGB" :
                      (!rbl__finite3(normal) || !(x*x + y*y + z*z > 0.0))? "NaN/Inf or zero normal" : NULL;
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblEncodeNormal: %s", bad); return; }
    double a[3];
    rbl__sanitizeNormal(normal, a);
    rbl__encode(a, encoding, out);
}

Vector3 RblDecodeNormal(const unsigned char in[3], int encoding)
{
    if ((in == NULL) || (!rbl__knownEncoding(encoding) && (encoding != RBL_NORMAL_NONE)))
    {
        TraceLog(LOG_WARNING, "RBL: RblDecodeNormal: %s; +Z returned", (in == NULL)? "NULL input" : "encoding is not HEMIOCT, XY or RGB");
        return rbl__flatNormal();
    }
    return rbl__decode(in, encoding);
}

#if defined(RBL_INSTRUMENTS)
// k-th smallest of v[0..n-1] (quickselect with Hoare partitioning; reorders v; expected O(n))
static double rbl__selectKth(double *v, long long n, long long k)
{
    long long lo = 0, hi = n - 1;
    while (hi > lo)
    {
        double pivot = v[lo + (hi - lo)/2];
        long long i = lo, j = hi;
        while (i <= j)
        {
            while (v[i] < pivot) i++;
            while (v[j] > pivot) j--;
            if (i <= j) { double t = v[i]; v[i] = v[j]; v[j] = t; i++; j--; }
        }
        if (k <= j) hi = j;             // v[lo..j] <= pivot <= v[i..hi], v[j+1..i-1] == pivot
        else if (k >= i) lo = i;
        else return v[k];
    }
    return v[k];
}

// Angle (degrees, double) between each input, normalised, and its encode + RblDecodeNormal result, as
// atan2(|a x d|, a.d): exact near 0 where acos(a.d) loses precision, and never NaN. Inputs below the
// hemisphere count with their clamping error; zero-length, NaN and Inf inputs are not counted.
// p99 is the nearest rank: the smallest error at least 99% of the errors do not exceed.
RblNormalErrorStats RblMeasureNormalEncoding(int encoding, const Vector3 *normals, int count)
{
    RblNormalErrorStats stats;
    memset(&stats, 0, sizeof(stats));
    if ((encoding != RBL_NORMAL_HEMIOCT) && (encoding != RBL_NORMAL_XY) && (encoding != RBL_NORMAL_RGB))
    {
        TraceLog(LOG_WARNING, "RBL: RblMeasureNormalEncoding: encoding %i is not HEMIOCT, XY or RGB", encoding);
        return stats;
    }
    if ((count < 0) || ((count > 0) && (normals == NULL))) { TraceLog(LOG_WARNING, "RBL: RblMeasureNormalEncoding: count %i with normals %p", count, (const void *)normals); return stats; }
    if (count == 0) return stats;

    double *errors = (double *)RBL_MALLOC((size_t)count*sizeof(double));
    if (errors == NULL) TraceLog(LOG_WARNING, "RBL: RblMeasureNormalEncoding: out of memory for %i errors (p99 reported as max)", count);
    double sum = 0.0;
    int n = 0, skipped = 0;
    for (int i = 0; i < count; i++)
    {
        Vector3 in = normals[i];
        double x = in.x, y = in.y, z = in.z, l = sqrt(x*x + y*y + z*z);
        if (!rbl__finite3(in) || !(l > 0.0)) { skipped++; continue; }     // no direction to compare with: not counted
        unsigned char code[3];
        double a[3];
        rbl__sanitizeNormal(in, a);
        rbl__encode(a, encoding, code);
        Vector3 d = rbl__decode(code, encoding);
        double dx = d.x, dy = d.y, dz = d.z;
        double cx = y*dz - z*dy, cy = z*dx - x*dz, cz = x*dy - y*dx;
        double deg = atan2(sqrt(cx*cx + cy*cy + cz*cz), x*dx + y*dy + z*dz)*(180.0/3.14159265358979323846);
        sum += deg;
        if (deg > stats.max) stats.max = deg;
        if (errors != NULL) errors[n] = deg;
        n++;
    }
    stats.count = n;
    if (skipped > 0) TraceLog(LOG_WARNING, "RBL: RblMeasureNormalEncoding: %i NaN/Inf or zero normals skipped", skipped);
    if (n > 0)
    {
        stats.mean = sum/n;
        long long rank = (long long)ceil(0.99*(double)n);
        if (rank < 1) rank = 1;
        stats.p99 = (errors != NULL)? rbl__selectKth(errors, n, rank - 1) : stats.max;
    }
    RBL_FREE(errors);
    return stats;
}
#endif

// ---- Texel access: every uncompressed raylib format, 8-bit ones in place, others through ImageFormat ----
typedef struct rbl__Texels {
    const unsigned char *u8;        // 8-bit data in place (GRAYSCALE, GRAY_ALPHA, R8G8B8, R8G8B8A8)
    const float *f32;               // Float data: in place (R32, R32G32B32, R32G32B32A32) or a converted RGBA copy
    Image converted;                // The copy to unload (data NULL when reading in place)
    int channels;                   // Channels per texel of u8 (1..4) or f32 (1, 3, 4)
    bool greyFloat;                 // Single-channel float source (R32, R16): channel 0 is the grey value
} rbl__Texels;

static inline bool rbl__formatConvertible(int format)
{
    return (format >= PIXELFORMAT_UNCOMPRESSED_GRAYSCALE) && (format <= PIXELFORMAT_UNCOMPRESSED_R16G16B16A16);
}

// Reads level 0 of an image (mipmaps of the source are ignored); false = out of memory
static bool rbl__openTexels(Image image, rbl__Texels *t)
{
    memset(t, 0, sizeof(*t));
    switch (image.format)
    {
        case PIXELFORMAT_UNCOMPRESSED_GRAYSCALE: t->u8 = (const unsigned char *)image.data; t->channels = 1; return true;
        case PIXELFORMAT_UNCOMPRESSED_GRAY_ALPHA: t->u8 = (const unsigned char *)image.data; t->channels = 2; return true;
        case PIXELFORMAT_UNCOMPRESSED_R8G8B8: t->u8 = (const unsigned char *)image.data; t->channels = 3; return true;
        case PIXELFORMAT_UNCOMPRESSED_R8G8B8A8: t->u8 = (const unsigned char *)image.data; t->channels = 4; return true;
        case PIXELFORMAT_UNCOMPRESSED_R32: t->f32 = (const float *)image.data; t->channels = 1; t->greyFloat = true; return true;
        case PIXELFORMAT_UNCOMPRESSED_R32G32B32: t->f32 = (const float *)image.data; t->channels = 3; return true;
        case PIXELFORMAT_UNCOMPRESSED_R32G32B32A32: t->f32 = (const float *)image.data; t->channels = 4; return true;
        default: break;
    }
    Image level0 = image;
    level0.mipmaps = 1;
    t->converted = ImageCopy(level0);
    if (t->converted.data == NULL) return false;
    ImageFormat(&t->converted, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32);      // lossless for every uncompressed format
    if ((t->converted.data == NULL) || (t->converted.format != PIXELFORMAT_UNCOMPRESSED_R32G32B32A32))
    {
        UnloadImage(t->converted);
        memset(t, 0, sizeof(*t));
        return false;
    }
    t->f32 = (const float *)t->converted.data;
    t->channels = 4;
    t->greyFloat = (image.format == PIXELFORMAT_UNCOMPRESSED_R16);     // R16 converts to (x, 0, 0, 1)
    return true;
}

static void rbl__closeTexels(rbl__Texels *t)
{
    if (t->converted.data != NULL) UnloadImage(t->converted);
    memset(t, 0, sizeof(*t));
}

// Texel i as RGBA: 8-bit channels /255, float channels as stored (not clamped); grey replicated, no alpha = 1
static inline void rbl__texelRGBA(const rbl__Texels *t, size_t i, float c[4])
{
    if (t->f32 != NULL)
    {
        const float *p = t->f32 + i*(size_t)t->channels;
        if (t->greyFloat) { c[0] = c[1] = c[2] = p[0]; c[3] = 1.0f; }
        else { c[0] = p[0]; c[1] = p[1]; c[2] = p[2]; c[3] = (t->channels == 4)? p[3] : 1.0f; }
        return;
    }
    const unsigned char *p = t->u8 + i*(size_t)t->channels;
    switch (t->channels)
    {
        case 1: c[0] = c[1] = c[2] = p[0]/255.0f; c[3] = 1.0f; break;
        case 2: c[0] = c[1] = c[2] = p[0]/255.0f; c[3] = p[1]/255.0f; break;
        case 3: c[0] = p[0]/255.0f; c[1] = p[1]/255.0f; c[2] = p[2]/255.0f; c[3] = 1.0f; break;
        default: c[0] = p[0]/255.0f; c[1] = p[1]/255.0f; c[2] = p[2]/255.0f; c[3] = p[3]/255.0f; break;
    }
}

// Texel i as RGBA bytes (float channels clamped to [0,1] and rounded)
static inline void rbl__texelBytes(const rbl__Texels *t, size_t i, unsigned char c[4])
{
    if (t->f32 != NULL)
    {
        float f[4];
        rbl__texelRGBA(t, i, f);
        for (int k = 0; k < 4; k++) c[k] = rbl__unorm8(f[k]);
        return;
    }
    const unsigned char *p = t->u8 + i*(size_t)t->channels;
    switch (t->channels)
    {
        case 1: c[0] = c[1] = c[2] = p[0]; c[3] = 255; break;
        case 2: c[0] = c[1] = c[2] = p[0]; c[3] = p[1]; break;
        case 3: c[0] = p[0]; c[1] = p[1]; c[2] = p[2]; c[3] = 255; break;
        default: c[0] = p[0]; c[1] = p[1]; c[2] = p[2]; c[3] = p[3]; break;
    }
}

// Red/grey channel of texel i: bytes (specular, occlusion) and heights (8-bit: /255, float: as stored)
static inline unsigned char rbl__texelRedByte(const rbl__Texels *t, size_t i)
{
    if (t->f32 != NULL) return rbl__unorm8(t->f32[i*(size_t)t->channels]);
    return t->u8[i*(size_t)t->channels];
}

static inline float rbl__texelRed(const rbl__Texels *t, size_t i)
{
    if (t->f32 != NULL) return t->f32[i*(size_t)t->channels];
    return t->u8[i*(size_t)t->channels]/255.0f;
}

// Source normal map texel -> tangent-space direction: n = c*2 - 1 for every format (8-bit: exactly as
// the RGB decode), DirectX maps flip y, |n|^2 < 1/4096 (e.g. 128,128,128) -> flat; left unnormalised
// (the encoder normalises it once, in double; NaN there -> flat)
static inline Vector3 rbl__sourceNormal(const rbl__Texels *t, size_t i, bool directX)
{
    float x, y, z;
    if ((t->u8 != NULL) && (t->channels >= 3))
    {
        const unsigned char *p = t->u8 + i*(size_t)t->channels;
        x = rbl__snorm(p[0]); y = rbl__snorm(p[1]); z = rbl__snorm(p[2]);
    }
    else
    {
        float c[4];
        rbl__texelRGBA(t, i, c);
        x = c[0]*2.0f - 1.0f; y = c[1]*2.0f - 1.0f; z = c[2]*2.0f - 1.0f;
    }
    if (directX) y = -y;
    return (x*x + y*y + z*z >= RBL__NORMAL_MIN_LEN2)? rbl__v3(x, y, z) : rbl__flatNormal();
}

// ---- sRGB, mip chains and gutter dilation -----------------------------------------------------------
static double rbl__srgbToLinear(double s)
{
    return (s <= 0.04045)? s/12.92 : pow((s + 0.055)/1.055, 2.4);
}

static double rbl__linearToSrgb(double l)
{
    return (l <= 0.0031308)? 12.92*l : 1.055*pow(l, 1.0/2.4) - 0.055;
}

// Exact 8-bit sRGB: decode table, and the linear values halfway between consecutive codes
// (encoding = how many midpoints lie below the value: round-to-nearest in the sRGB domain)
typedef struct rbl__Srgb {
    float toLinear[256];
    float midpoints[255];
} rbl__Srgb;

static void rbl__initSrgb(rbl__Srgb *s)
{
    for (int i = 0; i < 256; i++) s->toLinear[i] = (float)rbl__srgbToLinear(i/255.0);
    for (int i = 0; i < 255; i++) s->midpoints[i] = (float)rbl__srgbToLinear((i + 0.5)/255.0);
}

static inline unsigned char rbl__linearToSrgb8(const rbl__Srgb *s, float linear)
{
    int lo = 0, hi = 255;
    while (lo < hi)
    {
        int mid = (lo + hi)/2;
        if (s->midpoints[mid] < linear) lo = mid + 1; else hi = mid;
    }
    return (unsigned char)lo;
}

// raylib's mip rule (ImageMipmaps): halve each side (integer division, at least 1) until 1x1
static int rbl__mipCount(int width, int height)
{
    int count = 1;
    while ((width != 1) || (height != 1))
    {
        width = (width > 1)? width/2 : 1;
        height = (height > 1)? height/2 : 1;
        count++;
    }
    return count;
}

// Area-weighted box filter taps: destination texel d covers source [d*s, (d+1)*s), s = src/dst
// (exactly 2x2 for even sizes; an odd side spreads its extra texel over its neighbours)
typedef struct rbl__Taps {
    int first;                      // First source texel
    int count;                      // Source texels (1..4)
    float w[4];                     // Weights (sum 1)
} rbl__Taps;

static void rbl__mipTaps(int srcSize, int dstSize, rbl__Taps *taps)
{
    double scale = (double)srcSize/(double)dstSize;
    for (int d = 0; d < dstSize; d++)
    {
        double a = d*scale, b = (d + 1)*scale;
        int i0 = (int)floor(a), i1 = (int)ceil(b);
        if (i1 > srcSize) i1 = srcSize;
        taps[d].first = i0;
        taps[d].count = 0;
        for (int i = i0; (i < i1) && (taps[d].count < 4); i++)
        {
            double lo = (a > i)? a : (double)i, hi = (b < i + 1)? b : (double)(i + 1);
            taps[d].w[taps[d].count++] = (float)((hi - lo)/scale);
        }
    }
}

// Colour mip level (RGBA8 sRGB): RGB averaged in linear light, weighted by alpha when alphaWeighted
// (transparent texels' colour does not darken or tint the edges of cut-outs), alpha averaged linearly.
// premultiplied: texels hold sRGB colour x alpha; each is divided back, averaged as above, and the
// level stored premultiplied again (the same weighted mean as straight texels give)
static void rbl__downsampleColor(const unsigned char *src, int sw, unsigned char *dst, int dw, int dh,
                                 const rbl__Taps *tx, const rbl__Taps *ty, const rbl__Srgb *srgb, bool alphaWeighted, bool premultiplied)
{
    for (int y = 0; y < dh; y++)
    {
        for (int x = 0; x < dw; x++)
        {
            float sum[3] = { 0.0f, 0.0f, 0.0f }, sumA[3] = { 0.0f, 0.0f, 0.0f }, alpha = 0.0f;
            for (int j = 0; j < ty[y].count; j++)
            {
                const unsigned char *row = src + (size_t)(ty[y].first + j)*(size_t)sw*4;
                for (int i = 0; i < tx[x].count; i++)
                {
                    const unsigned char *p = row + (size_t)(tx[x].first + i)*4;
                    float w = ty[y].w[j]*tx[x].w[i], a = p[3]/255.0f;
                    for (int k = 0; k < 3; k++)
                    {
                        float l = !premultiplied? srgb->toLinear[p[k]] : ((p[3] > 0)? (float)rbl__srgbToLinear(fmin((double)p[k]/p[3], 1.0)) : 0.0f);
                        sum[k] += w*l;
                        sumA[k] += w*a*l;
                    }
                    alpha += w*a;
                }
            }
            unsigned char *out = dst + ((size_t)y*(size_t)dw + (size_t)x)*4;
            out[3] = rbl__unorm8(alpha);
            for (int k = 0; k < 3; k++)
            {
                if (premultiplied) out[k] = (out[3] > 0)? rbl__unorm8(rbl__linearToSrgb(sumA[k]/alpha)*out[3]/255.0) : 0;
                else out[k] = rbl__linearToSrgb8(srgb, (alphaWeighted && (alpha > 0.0f))? sumA[k]/alpha : sum[k]);
            }
        }
    }
}

// Alpha-tested coverage: the 8-bit threshold that passes a cutoff (texels with a/255 >= cutoff)
static int rbl__alphaThreshold(float cutoff) { int t = (int)ceil(cutoff*255.0 - 1e-9); return (t < 1)? 1 : ((t > 255)? 255 : t); }

// Texels of an RGBA8 level whose alpha passes the cutoff
static long long rbl__alphaCoverage(const unsigned char *rgba, size_t n, float cutoff)
{
    int t = rbl__alphaThreshold(cutoff);
    long long covered = 0;
    for (size_t i = 0; i < n; i++) covered += (rgba[i*4 + 3] >= t);
    return covered;
}

// Scales a level's alpha so that the share of texels passing the cutoff is level 0's (Castano,
// "Computing alpha mipmaps", 2010): without it, averaging thins alpha-tested foliage and fences
// level by level. With a' = min(255, round(a s)), exactly the texels with a >= k pass, for the k whose
// boundary s maps onto the threshold: the histogram gives every reachable share, the closest to the
// target is kept, and s puts k - 1/2 on t - 1/2 (between the two roundings). Colour is untouched
// (premultiplied texels are scaled with their alpha, which keeps the colour they hold).
static void rbl__keepAlphaCoverage(unsigned char *rgba, size_t n, float cutoff, double share0, bool premultiplied)
{
    size_t hist[256] = { 0 };
    for (size_t i = 0; i < n; i++) hist[rgba[i*4 + 3]]++;
    const int t = rbl__alphaThreshold(cutoff);
    const double want = share0*(double)n;
    size_t atLeast = 0;             // texels with alpha >= k, k from 255 down
    int bestK = t;
    double bestErr = -1.0;
    for (int k = 255; k >= 1; k--)
    {
        atLeast += hist[k];
        double err = fabs((double)atLeast - want);
        // Ties: the k nearest the threshold (the smallest change of alpha)
        if ((bestErr < 0.0) || (err < bestErr) || ((err == bestErr) && (abs(k - t) < abs(bestK - t)))) { bestErr = err; bestK = k; }
    }
    if (bestK == t) return;         // already the closest share: alpha unchanged
    const double scale = ((double)t - 0.5)/((double)bestK - 0.5);
    for (size_t i = 0; i < n; i++)
    {
        double a = floor(rgba[i*4 + 3]*scale + 0.5);
        if (a > 255.0) a = 255.0;
        if (premultiplied && (rgba[i*4 + 3] > 0))
            for (int k = 0; k < 3; k++) { double c = floor(rgba[i*4 + k]*a/rgba[i*4 + 3] + 0.5); rgba[i*4 + k] = (unsigned char)((c > a)? a : c); }
        rgba[i*4 + 3] = (unsigned char)a;
    }
}

// Linear mip level of a one-channel image (emissive mask)
static void rbl__downsampleLinear1(const unsigned char *src, int sw, unsigned char *dst, int dw, int dh,
                                   const rbl__Taps *tx, const rbl__Taps *ty)
{
    for (int y = 0; y < dh; y++)
    {
        for (int x = 0; x < dw; x++)
        {
            float sum = 0.0f;
            for (int j = 0; j < ty[y].count; j++)
                for (int i = 0; i < tx[x].count; i++)
                    sum += ty[y].w[j]*tx[x].w[i]*src[(size_t)(ty[y].first + j)*(size_t)sw + (size_t)(tx[x].first + i)];
            dst[(size_t)y*(size_t)dw + (size_t)x] = rbl__unorm8(sum/255.0f);
        }
    }
}

// Material mip level: normals decoded, averaged, renormalised (|average| < 1/64 -> flat), re-encoded with
// the same encoder; the other channels averaged linearly. Without a normal map the (constant) normal
// channels are copied.
static void rbl__downsampleMaterial(const unsigned char *src, int sw, unsigned char *dst, int dw, int dh,
                                    const rbl__Taps *tx, const rbl__Taps *ty, int encoding, bool hasNormal)
{
    const int normalChannels = (encoding == RBL_NORMAL_RGB)? 3 : 2;
    for (int y = 0; y < dh; y++)
    {
        for (int x = 0; x < dw; x++)
        {
            double n[3] = { 0.0, 0.0, 0.0 };
            float other[2] = { 0.0f, 0.0f };
            for (int j = 0; j < ty[y].count; j++)
            {
                const unsigned char *row = src + (size_t)(ty[y].first + j)*(size_t)sw*4;
                for (int i = 0; i < tx[x].count; i++)
                {
                    const unsigned char *p = row + (size_t)(tx[x].first + i)*4;
                    float w = ty[y].w[j]*tx[x].w[i];
                    if (hasNormal)
                    {
                        Vector3 d = rbl__decode(p, encoding);
                        n[0] += w*d.x; n[1] += w*d.y; n[2] += w*d.z;
                    }
                    for (int k = normalChannels; k < 4; k++) other[k - 2] += w*p[k];
                }
            }
            unsigned char *out = dst + ((size_t)y*(size_t)dw + (size_t)x)*4;
            if (hasNormal)
            {
                // An average shorter than 1/64 is quantisation noise left by cancelling directions
                // (e.g. two opposite codes): its direction means nothing, so it is the flat normal
                double l2 = n[0]*n[0] + n[1]*n[1] + n[2]*n[2];
                double a[3] = { 0.0, 0.0, 1.0 };
                if (l2 >= RBL__NORMAL_MIN_LEN2) { double l = sqrt(l2); a[0] = n[0]/l; a[1] = n[1]/l; a[2] = n[2]/l; }
                unsigned char code[3];
                rbl__encode(a, encoding, code);
                for (int k = 0; k < normalChannels; k++) out[k] = code[k];
            }
            else
            {
                for (int k = 0; k < normalChannels; k++) out[k] = src[k];
            }
            for (int k = normalChannels; k < 4; k++) out[k] = rbl__unorm8(other[k - 2]/255.0f);
        }
    }
}

// Nearest frame texel of every texel of a level (w x h of a w0 x h0 atlas): nearest[i] == i inside
// a frame, else the index of the nearest inside texel in Chebyshev distance (ties: the first found).
// Inside = touched by a frame scaled to the level (conservative: floor of the start, ceil of the end).
// Two-pass chessboard distance transform (Rosenfeld-Pfaltz, exact for this metric) that carries the
// source along: a texel inheriting its neighbour's source at distance d + 1 is at most that far from
// it, and d + 1 is the exact distance, so the source is a nearest one. O(texels + frame area).
static void rbl__nearestFrameTexels(const Rectangle *frames, int frameCount, int w0, int h0, int w, int h, int *nearest, int *dist)
{
    const size_t n = (size_t)w*(size_t)h;
    for (size_t i = 0; i < n; i++) { nearest[i] = -1; dist[i] = 0x3FFFFFFF; }
    const double sx = (double)w/w0, sy = (double)h/h0;
    for (int f = 0; f < frameCount; f++)
    {
        int x0 = (int)floor(frames[f].x*sx), x1 = (int)ceil(((double)frames[f].x + frames[f].width)*sx);
        int y0 = (int)floor(frames[f].y*sy), y1 = (int)ceil(((double)frames[f].y + frames[f].height)*sy);
        if (x0 > w - 1) x0 = w - 1;
        if (y0 > h - 1) y0 = h - 1;
        if (x1 <= x0) x1 = x0 + 1;
        if (y1 <= y0) y1 = y0 + 1;
        if (x1 > w) x1 = w;
        if (y1 > h) y1 = h;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++) { nearest[(size_t)y*w + x] = y*w + x; dist[(size_t)y*w + x] = 0; }
    }
    // Forward pass: left, up-left, up, up-right; backward pass: right, down-right, down, down-left
    for (int pass = 0; pass < 2; pass++)
    {
        const int step = (pass == 0)? 1 : -1, dy = -step;
        for (int yy = 0; yy < h; yy++)
        {
            const int y = (pass == 0)? yy : h - 1 - yy;
            const bool rowOk = (y + dy >= 0) && (y + dy < h);
            for (int xx = 0; xx < w; xx++)
            {
                const int x = (pass == 0)? xx : w - 1 - xx;
                const int i = y*w + x;
                if (dist[i] == 0) continue;
                int best = dist[i], src = nearest[i];
                const int xb = x - step;                           // the side already swept
                if ((xb >= 0) && (xb < w) && (dist[i - step] + 1 < best)) { best = dist[i - step] + 1; src = nearest[i - step]; }
                if (rowOk)
                {
                    const int r = (y + dy)*w;
                    for (int k = -1; k <= 1; k++)
                    {
                        const int xn = x + k;
                        if ((xn < 0) || (xn >= w)) continue;
                        if (dist[r + xn] + 1 < best) { best = dist[r + xn] + 1; src = nearest[r + xn]; }
                    }
                }
                dist[i] = best;
                nearest[i] = src;
            }
        }
    }
}

static void rbl__applyDilation(unsigned char *level, int bytesPerTexel, const int *nearest, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (nearest[i] != (int)i) memcpy(level + i*(size_t)bytesPerTexel, level + (size_t)nearest[i]*(size_t)bytesPerTexel, (size_t)bytesPerTexel);
}

// ---- Packing ----------------------------------------------------------------------------------------
// A map's size and format; false (logged) when it cannot be packed
static bool rbl__checkMap(Image image, const char *name, int width, int height)
{
    if (image.data == NULL) return true;      // absent
    if ((image.width != width) || (image.height != height))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: %s is %ix%i, the albedo %ix%i (every map must have the albedo's size)",
                 name, image.width, image.height, width, height);
        return false;
    }
    if (image.format >= PIXELFORMAT_COMPRESSED_DXT1_RGB)
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: %s has compressed format %i (decompress it first)", name, image.format);
        return false;
    }
    if (!rbl__formatConvertible(image.format))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: %s has unknown pixel format %i", name, image.format);
        return false;
    }
    return true;
}

static bool rbl__validateMaterialSource(const RblMaterialSource *s)
{
    const Image *albedo = &s->albedo;
    if (albedo->data == NULL) { TraceLog(LOG_WARNING, "RBL: RblPackMaterial: albedo is required (data is NULL)"); return false; }
    if ((albedo->width <= 0) || (albedo->height <= 0))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: albedo size %ix%i", albedo->width, albedo->height);
        return false;
    }
    // Levels of 4-byte texels must stay addressable by int and by MemAlloc's unsigned int
    if ((double)albedo->width*(double)albedo->height*4.0*4.0/3.0 + 64.0 > 2147483647.0)
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: albedo %ix%i is too large to pack", albedo->width, albedo->height);
        return false;
    }
    if (!rbl__checkMap(*albedo, "albedo", albedo->width, albedo->height) ||
        !rbl__checkMap(s->normal, "normal", albedo->width, albedo->height) ||
        !rbl__checkMap(s->specular, "specular", albedo->width, albedo->height) ||
        !rbl__checkMap(s->occlusion, "occlusion", albedo->width, albedo->height) ||
        !rbl__checkMap(s->emissive, "emissive", albedo->width, albedo->height)) return false;
    if (!rbl__finite(s->alphaCoverage) || (s->alphaCoverage < 0.0f) || (s->alphaCoverage >= 1.0f))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: alphaCoverage %g outside 0..1 (0 = off)", s->alphaCoverage);
        return false;
    }
    int encoding = (s->normalEncoding == RBL_NORMAL_NONE)? RBL_NORMAL_HEMIOCT : s->normalEncoding;
    if ((encoding != RBL_NORMAL_HEMIOCT) && (encoding != RBL_NORMAL_XY) && (encoding != RBL_NORMAL_RGB))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: normalEncoding %i is not 0, HEMIOCT, XY or RGB", s->normalEncoding);
        return false;
    }
    if ((encoding == RBL_NORMAL_RGB) && (s->specular.data != NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: RBL_NORMAL_RGB fills the material texture's RGB: specular has no channel left (use HEMIOCT or XY)");
        return false;
    }
    if ((s->frameCount < 0) || ((s->frameCount > 0) && (s->frames == NULL)))
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: %i frames at %p", s->frameCount, (const void *)s->frames);
        return false;
    }
    for (int i = 0; i < s->frameCount; i++)
    {
        Rectangle r = s->frames[i];
        bool ok = rbl__finite(r.x) && rbl__finite(r.y) && rbl__finite(r.width) && rbl__finite(r.height) &&
                  (r.width > 0.0f) && (r.height > 0.0f) && (r.x >= 0.0f) && (r.y >= 0.0f) &&
                  ((double)r.x + r.width <= albedo->width) && ((double)r.y + r.height <= albedo->height);
        if (!ok)
        {
            TraceLog(LOG_WARNING, "RBL: RblPackMaterial: frame %i (%g, %g, %g x %g) is empty or outside the %ix%i atlas",
                     i, r.x, r.y, r.width, r.height, albedo->width, albedo->height);
            return false;
        }
    }
    return true;
}

// An output Image of the whole chain (freeable with UnloadImage: MemAlloc is raylib's allocator)
static Image rbl__allocImage(int width, int height, int levels, int format)
{
    Image image;
    memset(&image, 0, sizeof(image));
    int bpp = (format == PIXELFORMAT_UNCOMPRESSED_GRAYSCALE)? 1 : 4;
    size_t size = 0;
    for (int l = 0, w = width, h = height; l < levels; l++)
    {
        size += (size_t)w*(size_t)h*(size_t)bpp;
        w = (w > 1)? w/2 : 1;
        h = (h > 1)? h/2 : 1;
    }
    image.data = MemAlloc((unsigned int)size);
    if (image.data == NULL) return image;
    image.width = width;
    image.height = height;
    image.mipmaps = levels;
    image.format = format;
    return image;
}

bool RblPackMaterial(const RblMaterialSource *source, RblPackedMaterial *packed)
{
    if ((source == NULL) || (packed == NULL)) { TraceLog(LOG_WARNING, "RBL: RblPackMaterial: NULL source or packed"); return false; }
    if (!rbl__validateMaterialSource(source)) return false;

    const int width = source->albedo.width, height = source->albedo.height;
    const size_t texels = (size_t)width*(size_t)height;
    const int encoding = (source->normalEncoding == RBL_NORMAL_NONE)? RBL_NORMAL_HEMIOCT : source->normalEncoding;
    const bool hasNormal = (source->normal.data != NULL), hasSpecular = (source->specular.data != NULL);
    const bool hasOcclusion = (source->occlusion.data != NULL), hasEmissive = (source->emissive.data != NULL);
    const bool hasMaterial = hasNormal || hasSpecular || hasOcclusion;
    const bool hasFrames = (source->frameCount > 0);
    const int levels = source->mipmaps? rbl__mipCount(width, height) : 1;

    RblPackedMaterial out;
    memset(&out, 0, sizeof(out));
    rbl__Texels albedoIn, normalIn, specularIn, occlusionIn, emissiveIn;
    memset(&albedoIn, 0, sizeof(albedoIn)); memset(&normalIn, 0, sizeof(normalIn)); memset(&specularIn, 0, sizeof(specularIn));
    memset(&occlusionIn, 0, sizeof(occlusionIn)); memset(&emissiveIn, 0, sizeof(emissiveIn));
    int *nearest = NULL, *dist = NULL;
    rbl__Taps *taps = NULL;
    bool ok = rbl__openTexels(source->albedo, &albedoIn) &&
              (!hasNormal || rbl__openTexels(source->normal, &normalIn)) &&
              (!hasSpecular || rbl__openTexels(source->specular, &specularIn)) &&
              (!hasOcclusion || rbl__openTexels(source->occlusion, &occlusionIn)) &&
              (!hasEmissive || rbl__openTexels(source->emissive, &emissiveIn));

    // Emissive: a mask when every texel is grey
    bool emissiveMask = true;
    if (ok && hasEmissive)
    {
        if ((emissiveIn.channels > 2) && !emissiveIn.greyFloat)
        {
            for (size_t i = 0; (i < texels) && emissiveMask; i++)
            {
                unsigned char c[4];
                rbl__texelBytes(&emissiveIn, i, c);
                emissiveMask = (c[0] == c[1]) && (c[1] == c[2]);
            }
        }
    }

    if (ok)
    {
        out.albedo = rbl__allocImage(width, height, levels, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
        ok = (out.albedo.data != NULL);
    }
    if (ok && hasMaterial)
    {
        out.material = rbl__allocImage(width, height, levels, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
        ok = (out.material.data != NULL);
    }
    if (ok && hasEmissive)
    {
        out.emissive = rbl__allocImage(width, height, levels, emissiveMask? PIXELFORMAT_UNCOMPRESSED_GRAYSCALE : PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
        ok = (out.emissive.data != NULL);
    }
    if (ok && hasFrames)
    {
        nearest = (int *)RBL_MALLOC(texels*sizeof(int));
        dist = (int *)RBL_MALLOC(texels*sizeof(int));
        ok = (nearest != NULL) && (dist != NULL);
    }
    if (ok && (levels > 1))
    {
        taps = (rbl__Taps *)RBL_MALLOC(((size_t)width + (size_t)height)*sizeof(rbl__Taps));
        ok = (taps != NULL);
    }

    if (ok)
    {
        // Level 0
        unsigned char *albedo = (unsigned char *)out.albedo.data;
        if ((albedoIn.u8 != NULL) && (albedoIn.channels == 4)) memcpy(albedo, albedoIn.u8, texels*4);
        else for (size_t i = 0; i < texels; i++) rbl__texelBytes(&albedoIn, i, albedo + i*4);

        if (hasMaterial)
        {
            unsigned char *material = (unsigned char *)out.material.data;
            const int normalChannels = (encoding == RBL_NORMAL_RGB)? 3 : 2;
            unsigned char flat[3];
            RblEncodeNormal(rbl__flatNormal(), encoding, flat);
            for (size_t i = 0; i < texels; i++)
            {
                unsigned char *p = material + i*4;
                if (hasNormal)
                {
                    double a[3];
                    rbl__sanitizeNormal(rbl__sourceNormal(&normalIn, i, source->normalDirectX), a);
                    unsigned char code[3];
                    rbl__encode(a, encoding, code);
                    for (int k = 0; k < normalChannels; k++) p[k] = code[k];
                }
                else for (int k = 0; k < normalChannels; k++) p[k] = flat[k];
                if (encoding != RBL_NORMAL_RGB) p[2] = hasSpecular? rbl__texelRedByte(&specularIn, i) : RBL__SPECULAR_DEFAULT;
                p[3] = hasOcclusion? rbl__texelRedByte(&occlusionIn, i) : RBL__OCCLUSION_DEFAULT;
            }
        }

        if (hasEmissive)
        {
            unsigned char *emissive = (unsigned char *)out.emissive.data;
            if (emissiveMask) for (size_t i = 0; i < texels; i++) emissive[i] = rbl__texelRedByte(&emissiveIn, i);
            else for (size_t i = 0; i < texels; i++) rbl__texelBytes(&emissiveIn, i, emissive + i*4);
        }

        // Levels 1.. from the level above; gutters dilated on every level
        double coverageTarget = -1.0;       // share of level 0's texels at or above the coverage cutoff (-1 = off)
        rbl__Srgb srgb;
        rbl__initSrgb(&srgb);
        const int emissiveBpp = emissiveMask? 1 : 4;
        size_t offset = 0, prevOffset = 0;      // texels before this level / the level above
        int pw = width, ph = height;            // size of the level above
        for (int l = 0, w = width, h = height; l < levels; l++)
        {
            unsigned char *albedoLevel = (unsigned char *)out.albedo.data + offset*4;
            unsigned char *materialLevel = hasMaterial? (unsigned char *)out.material.data + offset*4 : NULL;
            unsigned char *emissiveLevel = hasEmissive? (unsigned char *)out.emissive.data + offset*(size_t)emissiveBpp : NULL;
            if (l > 0)
            {
                // The level above is no longer a source once this one is built from it: scale it now
                if ((l > 1) && coverageTarget >= 0.0) rbl__keepAlphaCoverage((unsigned char *)out.albedo.data + prevOffset*4, (size_t)pw*(size_t)ph, source->alphaCoverage, coverageTarget, source->premultipliedAlpha);
                rbl__Taps *tx = taps, *ty = taps + w;
                rbl__mipTaps(pw, w, tx);
                rbl__mipTaps(ph, h, ty);
                rbl__downsampleColor((unsigned char *)out.albedo.data + prevOffset*4, pw, albedoLevel, w, h, tx, ty, &srgb, true, source->premultipliedAlpha);
                if (hasMaterial)
                    rbl__downsampleMaterial((unsigned char *)out.material.data + prevOffset*4, pw, materialLevel, w, h, tx, ty, encoding, hasNormal);
                if (hasEmissive && emissiveMask)
                    rbl__downsampleLinear1((unsigned char *)out.emissive.data + prevOffset, pw, emissiveLevel, w, h, tx, ty);
                else if (hasEmissive)
                    rbl__downsampleColor((unsigned char *)out.emissive.data + prevOffset*4, pw, emissiveLevel, w, h, tx, ty, &srgb, false, false);
            }
            if (hasFrames)
            {
                size_t n = (size_t)w*(size_t)h;
                rbl__nearestFrameTexels(source->frames, source->frameCount, width, height, w, h, nearest, dist);
                rbl__applyDilation(albedoLevel, 4, nearest, n);
                if (hasMaterial) rbl__applyDilation(materialLevel, 4, nearest, n);
                if (hasEmissive) rbl__applyDilation(emissiveLevel, emissiveBpp, nearest, n);
            }
            // Level 0's coverage is every level's target (measured after its gutters are dilated)
            if ((l == 0) && (source->alphaCoverage > 0.0f) && (levels > 1)) coverageTarget = (double)rbl__alphaCoverage(albedoLevel, (size_t)w*(size_t)h, source->alphaCoverage)/((double)w*(double)h);
            prevOffset = offset;
            offset += (size_t)w*(size_t)h;
            pw = w;
            ph = h;
            w = (w > 1)? w/2 : 1;
            h = (h > 1)? h/2 : 1;
        }
        if ((levels > 1) && (coverageTarget >= 0.0)) rbl__keepAlphaCoverage((unsigned char *)out.albedo.data + prevOffset*4, (size_t)pw*(size_t)ph, source->alphaCoverage, coverageTarget, source->premultipliedAlpha);

        out.layout.normalEncoding = hasNormal? encoding : RBL_NORMAL_NONE;
        out.layout.specular = hasSpecular;
        out.layout.occlusion = hasOcclusion;
        out.layout.emissive = !hasEmissive? RBL_EMISSIVE_NONE : (emissiveMask? RBL_EMISSIVE_MASK : RBL_EMISSIVE_RGB);
        out.layout.premultipliedAlpha = source->premultipliedAlpha;
    }
    else
    {
        TraceLog(LOG_WARNING, "RBL: RblPackMaterial: out of memory packing a %ix%i material", width, height);
        if (out.albedo.data != NULL) UnloadImage(out.albedo);
        if (out.material.data != NULL) UnloadImage(out.material);
        if (out.emissive.data != NULL) UnloadImage(out.emissive);
    }

    rbl__closeTexels(&albedoIn); rbl__closeTexels(&normalIn); rbl__closeTexels(&specularIn);
    rbl__closeTexels(&occlusionIn); rbl__closeTexels(&emissiveIn);
    RBL_FREE(nearest); RBL_FREE(dist); RBL_FREE(taps);
    if (ok) *packed = out;
    return ok;
}

void RblUnloadPackedMaterial(RblPackedMaterial *packed)
{
    if ((packed == NULL) || ((packed->albedo.data == NULL) && (packed->material.data == NULL) && (packed->emissive.data == NULL)))
    {
        TraceLog(LOG_WARNING, "RBL: RblUnloadPackedMaterial: %s", (packed == NULL)? "NULL packed" : "nothing packed (zero, or unloaded before)");
        return;
    }
    if (packed->albedo.data != NULL) UnloadImage(packed->albedo);
    if (packed->material.data != NULL) UnloadImage(packed->material);
    if (packed->emissive.data != NULL) UnloadImage(packed->emissive);
    memset(packed, 0, sizeof(*packed));
}

// ---- Authoring help: height -> normal, albedo -> height, height -> occlusion ------------------------
// A map for the Gen functions: present, sized and convertible; false (logged) otherwise
static bool rbl__checkGenInput(Image image, const char *function)
{
    if ((image.data == NULL) || (image.width <= 0) || (image.height <= 0) || (image.width > RBL_MAX_TARGET_SIZE) || (image.height > RBL_MAX_TARGET_SIZE))
    {
        TraceLog(LOG_WARNING, "RBL: %s: empty or oversized image (%ix%i, data %p; sides 1..RBL_MAX_TARGET_SIZE)", function, image.width, image.height, image.data);
        return false;
    }
    if (!rbl__formatConvertible(image.format))
    {
        TraceLog(LOG_WARNING, "RBL: %s: pixel format %i is compressed or unknown (decompress it first)", function, image.format);
        return false;
    }
    if ((double)image.width*(double)image.height*16.0 > 2147483647.0)
    {
        TraceLog(LOG_WARNING, "RBL: %s: %ix%i is too large", function, image.width, image.height);
        return false;
    }
    return true;
}

// Heights of every texel: red/grey channel, 8-bit as byte/255, float as stored (NaN/Inf -> 0); NULL = failure (logged)
static float *rbl__loadHeights(Image image, const char *function)
{
    rbl__Texels t;
    if (!rbl__openTexels(image, &t)) { TraceLog(LOG_WARNING, "RBL: %s: out of memory", function); return NULL; }
    size_t n = (size_t)image.width*(size_t)image.height;
    float *h = (float *)RBL_MALLOC(n*sizeof(float));
    if (h != NULL) for (size_t i = 0; i < n; i++) { float v = rbl__texelRed(&t, i); h[i] = rbl__finite(v)? v : 0.0f; }
    else TraceLog(LOG_WARNING, "RBL: %s: out of memory", function);
    rbl__closeTexels(&t);
    return h;
}

// Unit normal of the height field z = strength*h (texel units) at texel (x, y), central differences:
//   dh/dx  = (h[x+1] - h[x-1])/2,   dh/dup = (h[row-1] - h[row+1])/2   (row 0 is the top: up = row - 1)
//   n = normalize(-strength*dh/dx, -strength*dh/dup, 1)   (OpenGL convention: +Y = image up)
// Neighbours beyond the edge wrap (tiling maps) or clamp to the edge texel.
static Vector3 rbl__heightNormal(const float *h, int w, int hgt, int x, int y, float strength, bool wrap)
{
    int xl = x - 1, xr = x + 1, yu = y - 1, yd = y + 1;
    if (wrap)
    {
        xl = (xl + w)%w; xr = xr%w; yu = (yu + hgt)%hgt; yd = yd%hgt;
    }
    else
    {
        if (xl < 0) xl = 0;
        if (xr > w - 1) xr = w - 1;
        if (yu < 0) yu = 0;
        if (yd > hgt - 1) yd = hgt - 1;
    }
    double dhdx = ((double)h[(size_t)y*w + xr] - (double)h[(size_t)y*w + xl])*0.5;
    double dhdup = ((double)h[(size_t)yu*w + x] - (double)h[(size_t)yd*w + x])*0.5;
    double nx = -(double)strength*dhdx, ny = -(double)strength*dhdup, nz = 1.0;
    double inv = 1.0/sqrt(nx*nx + ny*ny + nz*nz);     // finite: float heights x strength cannot overflow double
    return rbl__v3((float)(nx*inv), (float)(ny*inv), (float)(nz*inv));
}

Image RblGenNormalMapFromHeight(Image height, float strength, bool wrap)
{
    Image out;
    memset(&out, 0, sizeof(out));
    if (!rbl__checkGenInput(height, "RblGenNormalMapFromHeight")) return out;
    if (!rbl__finite(strength)) { TraceLog(LOG_WARNING, "RBL: RblGenNormalMapFromHeight: strength is not finite"); return out; }
    const int w = height.width, hgt = height.height;
    float *h = rbl__loadHeights(height, "RblGenNormalMapFromHeight");
    if (h == NULL) return out;
    unsigned char *data = (unsigned char *)MemAlloc((unsigned int)((size_t)w*(size_t)hgt*4));
    if (data == NULL) { TraceLog(LOG_WARNING, "RBL: RblGenNormalMapFromHeight: out of memory"); RBL_FREE(h); return out; }
    for (int y = 0; y < hgt; y++)
    {
        for (int x = 0; x < w; x++)
        {
            Vector3 n = rbl__heightNormal(h, w, hgt, x, y, strength, wrap);
            unsigned char *p = data + ((size_t)y*w + x)*4;
            p[0] = rbl__quantizeSnorm(n.x);
            p[1] = rbl__quantizeSnorm(n.y);
            p[2] = rbl__quantizeSnorm(n.z);
            p[3] = 255;
        }
    }
    RBL_FREE(h);
    out.data = data;
    out.width = w;
    out.height = hgt;
    out.mipmaps = 1;
    out.format = PIXELFORMAT_UNCOMPRESSED_R8G8B8A8;
    return out;
}

Image RblGenHeightFromLuminance(Image albedo)
{
    Image out;
    memset(&out, 0, sizeof(out));
    if (!rbl__checkGenInput(albedo, "RblGenHeightFromLuminance")) return out;
    rbl__Texels t;
    if (!rbl__openTexels(albedo, &t)) { TraceLog(LOG_WARNING, "RBL: RblGenHeightFromLuminance: out of memory"); return out; }
    const size_t n = (size_t)albedo.width*(size_t)albedo.height;
    unsigned char *data = (unsigned char *)MemAlloc((unsigned int)n);
    if (data == NULL) { TraceLog(LOG_WARNING, "RBL: RblGenHeightFromLuminance: out of memory"); rbl__closeTexels(&t); return out; }
    rbl__Srgb srgb;
    rbl__initSrgb(&srgb);
    for (size_t i = 0; i < n; i++)
    {
        double lin[3];
        if (t.f32 != NULL)
        {
            float c[4];
            rbl__texelRGBA(&t, i, c);
            for (int k = 0; k < 3; k++) lin[k] = rbl__srgbToLinear((c[k] < 0.0f)? 0.0 : (c[k] > 1.0f)? 1.0 : (double)c[k]);
        }
        else
        {
            unsigned char c[4];
            rbl__texelBytes(&t, i, c);
            for (int k = 0; k < 3; k++) lin[k] = srgb.toLinear[c[k]];
        }
        data[i] = rbl__unorm8(0.2126*lin[0] + 0.7152*lin[1] + 0.0722*lin[2]);
    }
    rbl__closeTexels(&t);
    out.data = data;
    out.width = albedo.width;
    out.height = albedo.height;
    out.mipmaps = 1;
    out.format = PIXELFORMAT_UNCOMPRESSED_GRAYSCALE;
    return out;
}

Image RblGenOcclusionFromHeight(Image height, int radius, float strength)
{
    Image out;
    memset(&out, 0, sizeof(out));
    if (!rbl__checkGenInput(height, "RblGenOcclusionFromHeight")) return out;
    if ((radius < 0) || (radius > RBL_MAX_OCCLUSION_RADIUS) || !rbl__finite(strength) || (strength < 0.0f))
    {
        TraceLog(LOG_WARNING, "RBL: RblGenOcclusionFromHeight: radius %i (0..%i) or strength %g (finite, >= 0) out of range", radius, RBL_MAX_OCCLUSION_RADIUS, strength);
        return out;
    }
    const int w = height.width, hgt = height.height;
    const size_t n = (size_t)w*(size_t)hgt;
    float *h = rbl__loadHeights(height, "RblGenOcclusionFromHeight");
    if (h == NULL) return out;
    // Box means over the (2r+1)^2 window clipped to the image, separably with prefix sums: O(texels)
    double *rows = (double *)RBL_MALLOC(n*sizeof(double));
    double *prefix = (double *)RBL_MALLOC(((size_t)((w > hgt)? w : hgt) + 1)*sizeof(double));
    unsigned char *data = (unsigned char *)MemAlloc((unsigned int)n);
    if ((rows == NULL) || (prefix == NULL) || (data == NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblGenOcclusionFromHeight: out of memory");
        RBL_FREE(h); RBL_FREE(rows); RBL_FREE(prefix); MemFree(data);
        return out;
    }
    for (int y = 0; y < hgt; y++)
    {
        prefix[0] = 0.0;
        for (int x = 0; x < w; x++) prefix[x + 1] = prefix[x] + h[(size_t)y*w + x];
        for (int x = 0; x < w; x++)
        {
            int x0 = (x - radius < 0)? 0 : x - radius, x1 = (x + radius > w - 1)? w - 1 : x + radius;
            rows[(size_t)y*w + x] = (prefix[x1 + 1] - prefix[x0])/(double)(x1 - x0 + 1);
        }
    }
    for (int x = 0; x < w; x++)
    {
        prefix[0] = 0.0;
        for (int y = 0; y < hgt; y++) prefix[y + 1] = prefix[y] + rows[(size_t)y*w + x];
        for (int y = 0; y < hgt; y++)
        {
            int y0 = (y - radius < 0)? 0 : y - radius, y1 = (y + radius > hgt - 1)? hgt - 1 : y + radius;
            double mean = (prefix[y1 + 1] - prefix[y0])/(double)(y1 - y0 + 1);
            double depth = mean - h[(size_t)y*w + x];
            data[(size_t)y*w + x] = rbl__unorm8(1.0 - strength*((depth > 0.0)? depth : 0.0));
        }
    }
    RBL_FREE(h); RBL_FREE(rows); RBL_FREE(prefix);
    out.data = data;
    out.width = w;
    out.height = hgt;
    out.mipmaps = 1;
    out.format = PIXELFORMAT_UNCOMPRESSED_GRAYSCALE;
    return out;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: lights and the forward lit shader   >>lit
//----------------------------------------------------------------------------------
// prefix + a stage's parts (rbl__pass_*: its includes resolved by the embed step, dependencies first)
// in one allocated string, without the #include lines (GLSL has no include)
static char *rbl__joinStage(const char *prefix, const char *const *const *parts)
{
    size_t len = strlen(prefix);
    for (int p = 0; parts[p] != NULL; p++)
        for (int i = 0; parts[p][i] != NULL; i++) if (strncmp(parts[p][i], "#include", 8) != 0) len += strlen(parts[p][i]);
    char *text = (char *)RBL_MALLOC(len + 1);
    if (text == NULL) return NULL;
    size_t at = strlen(prefix);
    memcpy(text, prefix, at);
    for (int p = 0; parts[p] != NULL; p++)
        for (int i = 0; parts[p][i] != NULL; i++)
        {
            if (strncmp(parts[p][i], "#include", 8) == 0) continue;
            size_t l = strlen(parts[p][i]);
            memcpy(text + at, parts[p][i], l);
            at += l;
        }
    text[at] = '\0';
    return text;
}

// Compile a variant: the dialect's #version and words (dialect.glsl), the stage, the variant's
// defines, then each stage's parts. raylib substitutes its default shader when compilation fails;
// report that.
// What precedes a stage's sources in dialect glsl: #version, the dialect and stage (dialect.glsl), defines
static void rbl__stagePrologue(int glsl, bool vertex, const char *defines, char *out, size_t size)
{
    const char *version = (glsl == 300)? "#version 300 es\n#define RBL_GLSL_ES\n" : (glsl == 100)? "#version 100\n#define RBL_GLSL_ES\n" :
                          (glsl == 120)? "#version 120\n" : "#version 330\n";
    snprintf(out, size, "%s#define RBL_GLSL %i\n#define %s\n%s", version, glsl, vertex? "RBL_VERTEX_STAGE" : "RBL_FRAGMENT_STAGE", defines);
}

static Shader rbl__loadShaderVariant(const char *const *const *vs, const char *const *const *fs, const char *defines)
{
    int glsl = rbl__glsl();
    char vsPrefix[1800], fsPrefix[1800];        // the version lines and the defines (rbl__compileProgram: 1536 at most)
    rbl__stagePrologue(glsl, true, defines, vsPrefix, sizeof(vsPrefix));
    rbl__stagePrologue(glsl, false, defines, fsPrefix, sizeof(fsPrefix));
    Shader shader;
    memset(&shader, 0, sizeof(shader));
    if (glsl == 0)
    {
        snprintf(rbl__state.problem, sizeof(rbl__state.problem), "lit shaders need OpenGL 2.1+ or ES 2+; this context is %s", rbl__contextName());
        return shader;
    }
    char *vsFull = rbl__joinStage(vsPrefix, vs);
    char *fsFull = rbl__joinStage(fsPrefix, fs);
    if ((vsFull != NULL) && (fsFull != NULL)) shader = LoadShaderFromMemory(vsFull, fsFull);
    RBL_FREE(vsFull); RBL_FREE(fsFull);
    if ((shader.id == 0) || (shader.id == rlGetShaderIdDefault()))
    {
        // The caller logs it, under its own name
        if ((vsFull == NULL) || (fsFull == NULL)) snprintf(rbl__state.problem, sizeof(rbl__state.problem), "out of memory joining the shader sources");
        else snprintf(rbl__state.problem, sizeof(rbl__state.problem), "a shader variant failed to compile/link (defines: %.400s)", defines);
        if ((shader.id != 0) && (shader.locs != NULL) && (shader.locs != rlGetShaderLocsDefault())) MemFree(shader.locs);
        memset(&shader, 0, sizeof(shader));
    }
    return shader;
}

static const char *const rbl__uniformNames[RBL__U_COUNT] = {
    "rblLightCount", "rblLightPosition", "rblLightColor", "rblLightSpot", "rblLightAttenuation",
    "rblAmbient", "rblAmbientGround", "rblAmbientUp", "rblFog", "rblFogStart", "rblExposure",
    "rblShadowLight", "rblShadowMatrix", "rblShadowParams", "rblShadowBias", "rblShadowAxes", "rblShadowTiles",
    "rblAlphaCutoff", "rblSpecularColor", "rblRoughMetal", "rblEmissiveColor", "rblEmissiveIntensity", "rblInstancing",
    "rblGAlbedo", "rblGNormal", "rblGParams", "rblGDepth", "rblGAccum", "rblInvView", "rblEye", "mvp",
    "rblOutput", "rblOutputScale", "rblDepthLinear", "rblInvP", "rblViewAxis", "rblSoftDepth", "rblSoftDepthTexel", "rblCasterIdOn", "rblCasterDepth", "rblFrameTable",
    "rblTransmission", "rblRelief", "rblCasterTint", "rblGThin", "rblReliefIndex", "rblGridOrigin", "rblGridDims", "rblPolygon", "rblPolygonTable" };

static bool rbl__finiteNonNegative(float x) { return rbl__finite(x) && (x >= 0.0f); }

// Colours are authored in sRGB like every raylib Color; lighting runs in linear light
static float rbl__colorToLinear(unsigned char c) { return (float)rbl__srgbToLinear(c/255.0); }

// Defaults applied field by field into a zeroed struct, so the registry key has no padding garbage
static const char *rbl__normaliseLitDesc(RblLitShaderDesc in, RblLitShaderDesc *out)
{
    memset(out, 0, sizeof(*out));
    RblMaterialLayout m = in.material;
    if ((in.maxLights < 0) || (in.maxLights > RBL_MAX_LIGHTS)) return "maxLights outside 0..RBL_MAX_LIGHTS";
    if ((in.shading.lightFeatures & ~15) != 0) return "unknown lightFeatures bits";
    if ((m.normalEncoding < RBL_NORMAL_NONE) || (m.normalEncoding > RBL_NORMAL_RGB)) return "unknown material.normalEncoding";
    if ((m.emissive < RBL_EMISSIVE_NONE) || (m.emissive > RBL_EMISSIVE_RGB)) return "unknown material.emissive";
    if ((m.normalEncoding == RBL_NORMAL_RGB) && m.specular) return "an RGB normal map leaves no channel for specular";
    if ((in.shading.brdf < RBL_BRDF_LAMBERT) || (in.shading.brdf > RBL_BRDF_GGX)) return "unknown brdf";
    if ((in.shading.fog < RBL_FOG_NONE) || (in.shading.fog > RBL_FOG_EXP2)) return "unknown fog mode";
    if ((in.shading.tonemap < RBL_TONEMAP_NONE) || (in.shading.tonemap > RBL_TONEMAP_ACES)) return "unknown tonemap";
    if (!rbl__finiteNonNegative(in.shading.gamma) || (in.shading.gamma > 16.0f) || ((in.shading.gamma > 0.0f) && (in.shading.gamma < 0.0625f))) return "gamma outside 1/16..16 (0 = sRGB)";
    if ((in.debugOutput < 0) || (in.debugOutput >= RBL_DEBUG_OUTPUT_COUNT)) return "debugOutput not an RblDebugOutput";
    if ((in.shading.shadowMaps < 0) || (in.shading.shadowMaps > RBL_MAX_SHADOWS)) return "shadowMaps outside 0..RBL_MAX_SHADOWS";
    if ((in.shading.shadowFilter < 0) || (in.shading.shadowFilter > RBL_SHADOW_MAX_FILTER)) return "shadowFilter outside 0..RBL_SHADOW_MAX_FILTER";
    if (in.skinning && in.instanced) return "skinning applies to Models (vertex buffers), not to the instanced path";
    if (in.softParticles && in.deferred) return "soft particles blend: a forward variant, not a G-buffer one";
    if (in.skinning && !RBL_GPU_SKINNING) return "skinning needs raylib built with SUPPORT_GPU_SKINNING (then define RBL_GPU_SKINNING 1 before the header)";
    if ((m.height < RBL_CHANNEL_NONE) || (m.height > RBL_CHANNEL_A) || (m.thickness < RBL_CHANNEL_NONE) || (m.thickness > RBL_CHANNEL_A)) return "unknown material.height or material.thickness channel";
    // A scalar map takes a channel nothing else of the layout uses
    for (int c = RBL_CHANNEL_B; c <= RBL_CHANNEL_A; c++)
    {
        int users = (m.height == c) + (m.thickness == c) + ((c == RBL_CHANNEL_B)? (m.specular || (m.normalEncoding == RBL_NORMAL_RGB)) : m.occlusion);
        if (users > 1) return "material.height/thickness share a channel with another map (B: specular, RGB normal; A: occlusion)";
    }
    if ((in.reliefSteps < 0) || (in.reliefSteps > RBL_MAX_RELIEF_STEPS)) return "reliefSteps outside 0..RBL_MAX_RELIEF_STEPS";
    if (in.relief && (m.height == RBL_CHANNEL_NONE)) return "relief needs a height channel (material.height)";
    if (in.shadowTransmittance && ((in.shading.shadowMaps == 0) || in.deferred)) return "shadowTransmittance needs shadowMaps > 0 in a forward variant";

    out->maxLights = (in.maxLights == 0)? ((RBL_MAX_LIGHTS < 4)? RBL_MAX_LIGHTS : 4) : in.maxLights;
    out->shading.lightFeatures = (in.shading.lightFeatures == 0)? RBL_LIGHT_FEATURE_POINT : in.shading.lightFeatures;
    out->material.normalEncoding = m.normalEncoding;
    out->material.emissive = m.emissive;
    out->material.occlusion = m.occlusion;
    out->material.premultipliedAlpha = m.premultipliedAlpha;
    // A specular map is sampled only by a BRDF that reads it (or the debug view that shows it)
    out->material.specular = m.specular && ((in.shading.brdf != RBL_BRDF_LAMBERT) || (in.debugOutput == RBL_DEBUG_OUTPUT_SPECULAR));
    out->shading.brdf = in.shading.brdf;
    out->shading.fog = in.shading.fog;
    out->shading.tonemap = in.shading.tonemap;
    out->shading.gamma = in.shading.gamma;
    out->shading.linearOutput = in.shading.linearOutput;
    out->instanced = in.instanced;
    out->deferred = in.deferred;
    out->skinning = in.skinning;
    out->softParticles = in.softParticles;
    out->crossFade = in.crossFade;
    out->debugOutput = in.debugOutput;
    // Height and thickness are sampled only by the feature that reads them
    out->transmission = in.transmission;
    out->material.thickness = in.transmission? m.thickness : RBL_CHANNEL_NONE;
    out->relief = in.relief;
    out->material.height = in.relief? m.height : RBL_CHANNEL_NONE;
    out->reliefSteps = in.relief? ((in.reliefSteps == 0)? 16 : in.reliefSteps) : 0;
    out->shadowTransmittance = in.shadowTransmittance;
    // The grid needs GLSL 3 (texelFetch, integer indices): ES 2 and GL 2.1 keep the maxLights slots
    if (in.clustered && !in.deferred && (rbl__glsl() >= 300)) { out->clustered = true; out->maxLights = 0; }
    if (in.deferred)
    {
        // The geometry pass lights nothing: lighting-only fields cannot make two variants differ
        out->maxLights = 1; out->shading.lightFeatures = RBL_LIGHT_FEATURE_POINT; out->shading.fog = RBL_FOG_NONE; out->shading.tonemap = RBL_TONEMAP_NONE;
        out->shading.gamma = 0.0f; out->shading.linearOutput = false; out->debugOutput = 0;
        // Relief marches the scene's first 8 lights of every type: light i of the scene is slot i
        if (in.relief) { out->maxLights = (RBL_MAX_LIGHTS < 8)? RBL_MAX_LIGHTS : 8; out->shading.lightFeatures = 15; }
    }
    out->shading.shadowMaps = in.deferred? 0 : in.shading.shadowMaps;       // the geometry pass receives nothing
    out->shading.shadowFilter = (out->shading.shadowMaps == 0)? 0 : ((in.shading.shadowFilter == 0)? 2 : in.shading.shadowFilter);
    return NULL;
}

// A shadow map's compiled code in receivers (shadows.glsl RBL_SHADOW_FORMAT<k> + 4 RBL_SHADOW_KIND<k>)
// from its params.y (format + 4 x kind, kind 2..4 the cascade count: one code for every count)
#define RBL__SHADOW_CODE_DEFAULT 2      // directional through a casters target: what a receiver compiles first
static int rbl__shadowCode(float paramsY)
{
    int y = (int)(paramsY + 0.5f), kind = y/4;
    return (y - 4*kind) + 4*((kind > 2)? 2 : kind);
}

// Codes of maps 0..maps-1 in 4 bits each: the scene's first count maps (uniform data as shadows.glsl
// reads them), the default for the rest (a program samples only maps the scene gives)
static int rbl__shadowKindsOf(const float (*uniforms)[48], int count, int maps)
{
    int kinds = 0;
    for (int k = 0; k < maps; k++) kinds |= ((k < count)? rbl__shadowCode(uniforms[k][17]) : RBL__SHADOW_CODE_DEFAULT) << (4*k);
    return kinds;
}

// Receiver defines: each map's kind and format (shadowKinds: rbl__shadowKindsOf), appended after
// rbl__litDefines; returns the bytes written
static size_t rbl__shadowDefines(int maps, int shadowKinds, char *out, size_t size)
{
    size_t used = 0;
    bool omni = false, cascades = false;
    for (int k = 0; (k < maps) && (used < size); k++)
    {
        int code = (shadowKinds >> (4*k)) & 15;
        omni = omni || (code/4 == 1); cascades = cascades || (code/4 == 2);
        used += (size_t)snprintf(out + used, size - used, "#define RBL_SHADOW_KIND%i %i\n#define RBL_SHADOW_FORMAT%i %i\n", k, code/4, k, code%4);
    }
    if (omni && (used < size)) used += (size_t)snprintf(out + used, size - used, "#define RBL_SHADOW_OMNI\n");
    if (cascades && (used < size)) used += (size_t)snprintf(out + used, size - used, "#define RBL_SHADOW_CASCADES\n");
    return (used < size)? used : size - 1;
}

// Variant defines: one line per compiled feature
static void rbl__litDefines(const RblLitShaderDesc *d, char *out, size_t size)
{
    const RblMaterialLayout *m = &d->material;
    bool view = !d->deferred && ((d->shading.brdf != RBL_BRDF_LAMBERT) || (d->shading.fog != RBL_FOG_NONE));   // the G-buffer stores no view
    int n = snprintf(out, size, "#define RBL_LIGHTS %i\n#define RBL_BRDF %i\n#define RBL_NORMAL_ENCODING %i\n#define RBL_EMISSIVE %i\n"
                     "#define RBL_FOG %i\n#define RBL_TONEMAP %i\n#define RBL_SHADOWS %i\n#define RBL_SHADOW_FILTER %i\n%s%s%s%s%s%s%s",
                     d->maxLights, d->shading.brdf, m->normalEncoding, m->emissive, d->shading.fog, d->shading.tonemap, d->shading.shadowMaps, d->shading.shadowFilter,
                     (d->shading.lightFeatures & RBL_LIGHT_FEATURE_DIRECTIONAL)? "#define RBL_LIGHT_DIRECTIONAL\n" : "",
                     (d->shading.lightFeatures & RBL_LIGHT_FEATURE_SPOT)? "#define RBL_LIGHT_SPOT\n" : "",
                     (d->shading.lightFeatures & RBL_LIGHT_FEATURE_CLASSIC_FALLOFF)? "#define RBL_LIGHT_CLASSIC\n" : "",
                     m->specular? "#define RBL_SPECULAR\n" : "", m->occlusion? "#define RBL_OCCLUSION\n" : "",
                     view? "#define RBL_VIEW_VECTOR\n" : "", d->shading.linearOutput? "#define RBL_LINEAR_OUTPUT\n" : "");
    if ((n > 0) && ((size_t)n < size) && (d->shading.gamma > 0.0f)) n += snprintf(out + n, size - (size_t)n, "#define RBL_GAMMA %.9g\n", d->shading.gamma);
    if ((n > 0) && ((size_t)n < size) && d->skinning) n += snprintf(out + n, size - (size_t)n, "#define RBL_SKINNING\n#define RBL_MAX_BONES %i\n", RBL_MAX_BONES);
    if ((n > 0) && ((size_t)n < size) && d->softParticles) n += snprintf(out + n, size - (size_t)n, "#define RBL_SOFT_PARTICLES\n");
    if ((n > 0) && ((size_t)n < size) && d->crossFade) n += snprintf(out + n, size - (size_t)n, "#define RBL_CROSS_FADE\n");
    // The caster identity: shadow receivers and G-buffer geometry variants (rbl__compileProgram adds it to casters)
    if ((n > 0) && ((size_t)n < size) && ((d->shading.shadowMaps > 0) || d->deferred)) n += snprintf(out + n, size - (size_t)n, "#define RBL_CASTER_ID\n");
    if ((n > 0) && ((size_t)n < size) && m->premultipliedAlpha) n += snprintf(out + n, size - (size_t)n, "#define RBL_PREMULTIPLIED_ALPHA\n");
    if ((n > 0) && ((size_t)n < size) && d->transmission) n += snprintf(out + n, size - (size_t)n, "#define RBL_TRANSMISSION\n");
    if ((n > 0) && ((size_t)n < size) && (m->thickness != RBL_CHANNEL_NONE)) n += snprintf(out + n, size - (size_t)n, "#define RBL_THICKNESS_CHANNEL %i\n", m->thickness + 2);
    if ((n > 0) && ((size_t)n < size) && (m->height != RBL_CHANNEL_NONE)) n += snprintf(out + n, size - (size_t)n, "#define RBL_HEIGHT_CHANNEL %i\n", m->height + 2);
    if ((n > 0) && ((size_t)n < size) && d->relief) n += snprintf(out + n, size - (size_t)n, "#define RBL_RELIEF_STEPS %i\n", d->reliefSteps);
    if ((n > 0) && ((size_t)n < size) && d->shadowTransmittance) n += snprintf(out + n, size - (size_t)n, "#define RBL_SHADOW_TINT\n");
    if ((n > 0) && ((size_t)n < size) && d->clustered) n += snprintf(out + n, size - (size_t)n, "#define RBL_LIGHT_GRID\n");
    if ((n > 0) && ((size_t)n < size) && (d->debugOutput > 0)) snprintf(out + n, size - (size_t)n, "#define RBL_DEBUG_OUTPUT %i\n", d->debugOutput);
}

//----------------------------------------------------------------------------------
// Module Internal Functions: the program registry   >>registry
//----------------------------------------------------------------------------------
// Every program the header compiles is one registry entry, keyed by what changes the code. Lit
// programs go out one per RblLoadLitShader call, each its own GL program, so raylib's UnloadShader
// or UnloadMaterial on one copy deletes that program alone (as with raylib's LoadShader); casters
// and G-buffer passes are the header's own, shared by key among their holders. raylib may delete a
// lit program behind the registry's back: an entry is checked against GL before a draw uses it.

// GL name queries rlgl does not wrap, through raylib's loader (desktop, ES and WebGL all have them)
typedef unsigned char (RBL__GLAPI *rbl__GlIsName)(unsigned int name);
enum { RBL__GL_PROGRAM = 0, RBL__GL_TEXTURE, RBL__GL_VERTEX_ARRAY, RBL__GL_QUERIES };

// Whether name is a live GL object of that kind; true where the loader gives no query (cannot tell)
static bool rbl__glIsLive(int which, unsigned int name)
{
    if (name == 0) return false;
    if (!rbl__glUsable()) return true;          // no context to ask
    // rlGetProcAddress calls raylib's loader, which exists once rlgl is up (its default texture made)
    if (!rbl__state.glLooked && (rbl__glsl() != 0) && (rlGetTextureIdDefault() != 0))
    {
        rbl__state.glIs[RBL__GL_PROGRAM] = rlGetProcAddress("glIsProgram");
        rbl__state.glIs[RBL__GL_TEXTURE] = rlGetProcAddress("glIsTexture");
        rbl__state.glIs[RBL__GL_VERTEX_ARRAY] = (rbl__glsl() >= 300)? rlGetProcAddress("glIsVertexArray") : NULL;
        rbl__state.glGetUniformfv = rlGetProcAddress("glGetUniformfv");
        rbl__state.glLooked = true;
    }
    if (rbl__state.glIs[which] == NULL) return true;
    rbl__GlIsName is;
    memcpy(&is, &rbl__state.glIs[which], sizeof(is));       // ISO C: no cast between object and function pointers
    return is(name) != 0;
}

// A lit program is live while GL still has it as the header compiled it: a deleted id, or one GL
// gave to another program since, no longer answers with the registry's location of rblAlphaCutoff
// (every lit and caster variant declares it). Casters and passes never leave the header.
static bool rbl__programAlive(const rbl__Program *p)
{
    if ((p->key.kind != RBL__KIND_LIT) || !rbl__glUsable()) return true;     // no context: nothing to ask
    return (p->loc[RBL__U_ALPHA_CUTOFF] != -1) && rbl__glIsLive(RBL__GL_PROGRAM, p->shader.id) &&
           (rlGetLocationUniform(p->shader.id, "rblAlphaCutoff") == p->loc[RBL__U_ALPHA_CUTOFF]);
}

// raylib's DrawModel/DrawMesh upload a lit program's colDiffuse, matrices and textures, none of the
// header's material values. Each header draw leaves a sentinel in the program's mvp (raylib's draws
// always overwrite it) and the next header use reads it back: anything else means raylib drew with
// the program since, with the values the last header draw left (said once a program)
typedef void (RBL__GLAPI *rbl__GlGetUniformfv)(unsigned int program, int location, float *params);
static Matrix rbl__mvpSentinel(void)
{
    Matrix m;
    memset(&m, 0, sizeof(m));
    m.m15 = -8.125f;
    return m;
}

// After a header draw with p (bound): the sentinel
static void rbl__markDrawn(const rbl__Program *p)
{
    int loc = p->shader.locs[SHADER_LOC_MATRIX_MVP];
    if ((p->key.kind == RBL__KIND_LIT) && !p->raylibNoted && (loc != -1)) rlSetUniformMatrix(loc, rbl__mvpSentinel());
}

// Before a header use of p: whether raylib drew with it since the last header draw
static void rbl__checkRaylibDrew(rbl__Program *p)
{
    int loc = p->shader.locs[SHADER_LOC_MATRIX_MVP];
    if ((p->key.kind != RBL__KIND_LIT) || p->raylibNoted || (loc == -1) || (rbl__state.glGetUniformfv == NULL) || !rbl__glUsable()) return;
    rbl__GlGetUniformfv get;
    memcpy(&get, &rbl__state.glGetUniformfv, sizeof(get));
    float m[16];
#if defined(__EMSCRIPTEN__)
    rlEnableShader(p->shader.id);           // emscripten's WebGL layer resolves the location in the bound program only
    get(p->shader.id, loc, m);
    rlDisableShader();
#else
    get(p->shader.id, loc, m);
#endif
    bool sentinel = (m[15] == -8.125f);
    for (int i = 0; (i < 15) && sentinel; i++) sentinel = (m[i] == 0.0f);
    if (sentinel) return;
    TraceLog(LOG_WARNING, "RBL: lit program %u was drawn by raylib's DrawModel/DrawMesh, which uploads colDiffuse, matrices and textures only: "
                          "roughness, metalness, shininess, specular, emission and alpha cutoff were the last header draw's, and shadow maps of other kinds than its first compile's (omni, cascades) unsampled (draw Models with RblDrawModel/RblDrawMesh)", p->shader.id);
    p->raylibNoted = true;
}

static bool rbl__buried(unsigned int id, const int *locs)
{
    for (int i = 0; i < rbl__state.deadCount; i++) if ((rbl__state.dead[i].id == id) && (rbl__state.dead[i].locs == locs)) return true;
    return false;
}

// Remembers a dead handle so its copies are refused (out of memory: forgotten, the GL probe remains)
static void rbl__bury(unsigned int id, const int *locs)
{
    if (rbl__buried(id, locs)) return;
    if (rbl__state.deadCount == rbl__state.deadCapacity)
    {
        int capacity = (rbl__state.deadCapacity > 0)? rbl__state.deadCapacity*2 : 16;
        rbl__DeadHandle *dead = (rbl__DeadHandle *)RBL_REALLOC(rbl__state.dead, (size_t)capacity*sizeof(rbl__DeadHandle));
        if (dead == NULL) return;
        rbl__state.dead = dead;
        rbl__state.deadCapacity = capacity;
    }
    rbl__state.dead[rbl__state.deadCount].id = id;
    rbl__state.dead[rbl__state.deadCount].locs = locs;
    rbl__state.deadCount++;
}

// Takes entry p (allocated) out of the registry and frees it and its registry locs
static void rbl__removeProgram(rbl__Program *p)
{
    for (int i = 0; i < rbl__state.programCount; i++)
    {
        if (rbl__state.programs[i] != p) continue;
        rbl__state.programs[i] = rbl__state.programs[--rbl__state.programCount];
        break;
    }
    // An instanced program's resident-sprite variant is the header's: it goes with the program (and
    // a variant going alone, forgotten, is no longer its program's)
    // Receiver variants for other map kinds likewise
    for (int i = 0; i < rbl__state.programCount; i++)
    {
        rbl__Program *v = rbl__state.programs[i];
        if (v->shadowVariant == p) v->shadowVariant = NULL;
        if (v->shadowBase != p) continue;
        v->shadowBase = NULL;
        if (rbl__glUsable() && rbl__glIsLive(RBL__GL_PROGRAM, v->shader.id)) rlUnloadShaderProgram(v->shader.id);
        rbl__removeProgram(v);
        i = -1;                     // the registry was reordered
    }
    if (p->key.sprites)
        for (int i = 0; i < rbl__state.programCount; i++)
        {
            if (rbl__state.programs[i]->spriteVariant == p) rbl__state.programs[i]->spriteVariant = NULL;
            if (rbl__state.programs[i]->polygonVariant == p) rbl__state.programs[i]->polygonVariant = NULL;
            if (rbl__state.programs[i]->recordVariant == p) rbl__state.programs[i]->recordVariant = NULL;
        }
    rbl__Program *own[3] = { p->spriteVariant, p->polygonVariant, p->recordVariant };     // (a sprite variant's own polygon variant goes with it)
    p->spriteVariant = NULL; p->polygonVariant = NULL; p->recordVariant = NULL;
    for (int k = 0; k < 3; k++)
    {
        rbl__Program *v = own[k];
        if (v == NULL) continue;
        if (rbl__glUsable() && rbl__glIsLive(RBL__GL_PROGRAM, v->shader.id)) rlUnloadShaderProgram(v->shader.id);
        rbl__removeProgram(v);
    }
    if ((p->shader.locs != NULL) && (p->shader.locs != rlGetShaderLocsDefault())) MemFree(p->shader.locs);
    RBL_FREE(p);
}

// A lit program deleted outside the header (raylib's UnloadShader or UnloadMaterial: allowed): its
// entry goes, its handle is remembered as dead, the GL name is not deleted again
static void rbl__forgetProgram(rbl__Program *p)
{
    TraceLog(LOG_DEBUG, "RBL: lit program %u was unloaded outside the header (UnloadMaterial/UnloadShader): forgotten", p->shader.id);
    if (p->key.kind == RBL__KIND_LIT) rbl__bury(p->shader.id, p->handleLocs);
    rbl__removeProgram(p);
}

// Registered lit program id, or NULL (not checked against GL: rbl__resolveShader does that)
static rbl__Program *rbl__findLit(unsigned int id)
{
    for (int i = 0; (id != 0) && (i < rbl__state.programCount); i++)
    {
        rbl__Program *p = rbl__state.programs[i];
        if ((p->shader.id == id) && (p->key.kind == RBL__KIND_LIT)) return p;
    }
    return NULL;
}

// What a Material's shader is to the header: one of its live lit programs (*program), another live
// program (the caller's own, drawn as raylib would: *program NULL), or not drawable (the reason).
// Only the Shader's id and locs pointer are compared: a lit program's locs are the registry's.
static const char *rbl__resolveShader(Shader shader, rbl__Program **program)
{
    *program = NULL;
    if (shader.id == 0) return "the material has no shader (id 0: a zero Material, or a lit program that failed to load or was unloaded)";
    rbl__Program *p = rbl__findLit(shader.id);
    if ((p != NULL) && !rbl__programAlive(p)) { rbl__forgetProgram(p); p = NULL; }
    if (p != NULL)
    {
        if (p->handleLocs == shader.locs) { *program = p; return NULL; }
        return "the shader carries a live lit program's id but not its handle (a stale copy, or a Shader assembled by hand)";
    }
    if (rbl__buried(shader.id, shader.locs)) return "a stale copy of a lit shader unloaded earlier (RblUnloadLitShader, UnloadShader or UnloadMaterial)";
    if (!rbl__glIsLive(RBL__GL_PROGRAM, shader.id)) return "the shader's program does not exist (unloaded?)";
    if (shader.locs == NULL) return "the shader has no locations (locs NULL)";
    return NULL;
}

static void rbl__uploadScene(rbl__Program *p);

// Compile a program for key into a new registry entry; NULL (problem set) on failure
static rbl__Program *rbl__compileProgram(const rbl__ProgramKey *key)
{
    if (rbl__state.programCount >= RBL_SHADER_CACHE_SIZE) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "program registry full (RBL_SHADER_CACHE_SIZE = %i programs)", RBL_SHADER_CACHE_SIZE); return NULL; }
    if (rbl__state.programCount == rbl__state.programCapacity)
    {
        int capacity = (rbl__state.programCapacity > 0)? rbl__state.programCapacity*2 : 16;
        rbl__Program **programs = (rbl__Program **)RBL_REALLOC(rbl__state.programs, (size_t)capacity*sizeof(rbl__Program *));
        if (programs == NULL) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "out of memory for the program registry"); return NULL; }
        rbl__state.programs = programs;
        rbl__state.programCapacity = capacity;
    }
    rbl__Program *p = (rbl__Program *)RBL_CALLOC(1, sizeof(rbl__Program));
    if (p == NULL) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "out of memory for the program registry"); return NULL; }
    const RblLitShaderDesc *d = &key->desc;
    char defines[1536];
    rbl__litDefines(d, defines, sizeof(defines));
    size_t used = strlen(defines);
    used += rbl__shadowDefines(d->shading.shadowMaps, key->shadowKinds, defines + used, sizeof(defines) - used);
    if ((key->kind == RBL__KIND_CASTER) && (d->shading.shadowMaps == 0)) used += (size_t)snprintf(defines + used, sizeof(defines) - used, "#define RBL_CASTER_ID\n");
    if ((key->kind == RBL__KIND_CASTER) && (key->pass == 1) && (used < sizeof(defines))) snprintf(defines + used, sizeof(defines) - used, "#define RBL_CASTER_TRANSMIT\n");
    // G-buffer passes read RT2 as RGBA8 (caster identity in ba) on ES, or where the G-buffer receives shadows
    if ((key->kind == RBL__KIND_PASS) && ((rbl__glsl() == 300) || (d->shading.shadowMaps > 0))) snprintf(defines + used, sizeof(defines) - used, "#define RBL_GB_PARAMS_RGBA\n");
    if (key->sprites & 1) { size_t l = strlen(defines); snprintf(defines + l, sizeof(defines) - l, "#define RBL_SPRITE_BUFFER\n"); }
    if (key->sprites & 2) { size_t l = strlen(defines); snprintf(defines + l, sizeof(defines) - l, "#define RBL_POLYGONS\n"); }
    if (key->sprites & 4) { size_t l = strlen(defines); snprintf(defines + l, sizeof(defines) - l, "#define RBL_BATCH_RECORD\n"); }
    // The thin target (RT4): every geometry variant writes it where the context has 5 draw buffers;
    // light passes of a G-buffer with it read it
    bool thinPass = (key->kind == RBL__KIND_PASS) && (d->transmission || key->gbufferRelief);
    if ((key->kind == RBL__KIND_LIT) && d->deferred && (d->transmission || d->relief) && (rbl__maxDrawBuffers() < 5))
    {
        snprintf(rbl__state.problem, sizeof(rbl__state.problem), "a deferred transmission or relief variant needs a 5th render target (GL_MAX_DRAW_BUFFERS %i)", rbl__maxDrawBuffers());
        RBL_FREE(p);
        return NULL;
    }
    if ((thinPass || ((key->kind == RBL__KIND_LIT) && d->deferred)) && (rbl__maxDrawBuffers() >= 5)) { size_t l = strlen(defines); snprintf(defines + l, sizeof(defines) - l, "#define RBL_GB_THIN\n"); }
    if (key->gbufferRelief) { size_t l = strlen(defines); snprintf(defines + l, sizeof(defines) - l, "#define RBL_GB_RELIEF\n"); }
    if (((key->kind == RBL__KIND_PASS) || d->deferred || d->instanced) && (rbl__needsGlsl3(d->instanced? "instanced billboards" : "deferred passes") != NULL)) { RBL_FREE(p); return NULL; }
    Shader shader;
    if (key->kind == RBL__KIND_COMPOSITE)
        shader = rbl__loadShaderVariant(rbl__pass_scene_composite_vs, rbl__pass_scene_composite_fs, (rbl__glsl() == 100)? "#extension GL_EXT_frag_depth : enable\n" : "");
    else if (key->kind == RBL__KIND_PASS)
    {
        static const char *const *const *const vs[RBL__PASS_COUNT] = { rbl__pass_fullscreen_vs, rbl__pass_volume_vs, rbl__pass_fullscreen_vs, rbl__pass_fullscreen_vs, rbl__pass_volume_vs };
        static const char *const *const *const fs[RBL__PASS_COUNT] = { rbl__pass_deferred_fullscreen_fs, rbl__pass_deferred_volume_fs, rbl__pass_deferred_resolve_fs,
                                                                       rbl__pass_deferred_fullscreen_fs, rbl__pass_deferred_volume_fs };
        if ((key->pass == RBL__PASS_FULLSCREEN_COUNT) || (key->pass == RBL__PASS_VOLUME_COUNT))
        {
            size_t l = strlen(defines);
            snprintf(defines + l, sizeof(defines) - l, "#define RBL_COUNT_LIGHTS\n");
        }
        shader = rbl__loadShaderVariant(vs[key->pass], fs[key->pass], defines);
    }
    else
    {
        const char *const *const *fs = (key->kind == RBL__KIND_CASTER)? rbl__pass_shadow_caster_fs : (d->deferred? rbl__pass_gbuffer_fs : rbl__pass_lit_fs);
        shader = rbl__loadShaderVariant((d->instanced || (key->sprites & 4))? rbl__pass_lit_instanced_vs : rbl__pass_lit_vs, fs, defines);
    }
    if (shader.id == 0) { RBL_FREE(p); return NULL; }
    // GL hands out the names of deleted programs again: an entry still holding this id was deleted
    // outside the header
    for (int i = 0; i < rbl__state.programCount; i++)
        if (rbl__state.programs[i]->shader.id == shader.id) { rbl__forgetProgram(rbl__state.programs[i]); i--; }

    rbl__state.programs[rbl__state.programCount++] = p;
    rbl__state.closed = false;      // used again after RblClose
    p->key = *key;
    p->shader = shader;
    // Samplers exist only where the layout uses them (-1 otherwise), so nothing absent is bound
    p->shader.locs[SHADER_LOC_VECTOR_VIEW] = GetShaderLocation(shader, "viewPos");
    p->shader.locs[SHADER_LOC_MAP_NORMAL] = GetShaderLocation(shader, "texture2");
    p->shader.locs[SHADER_LOC_MAP_EMISSION] = GetShaderLocation(shader, "texture5");
    // The fade stream is the header's own: raylib's DrawMesh must not bind a Model's (perhaps absent)
    // texcoord2 buffer there; unbound, the attribute is constant and its weight 0
    p->shader.locs[SHADER_LOC_VERTEX_TEXCOORD02] = -1;
    p->fadeClipLoc = (d->crossFade && !d->instanced)? rlGetLocationAttrib(shader.id, "rblFadeClip") : -1;
    p->casterIdLoc = ((key->kind != RBL__KIND_PASS) && !d->instanced && ((key->kind == RBL__KIND_CASTER) || (d->shading.shadowMaps > 0) || d->deferred))?
                     rlGetLocationAttrib(shader.id, "rblCasterId") : -1;
    for (int u = 0; u < RBL__U_COUNT; u++) p->loc[u] = rlGetLocationUniform(shader.id, rbl__uniformNames[u]);
    p->refs = 1;
    rlEnableShader(shader.id);
    if (d->softParticles)
    {
        int unit = RBL_SCENE_DEPTH_TEXTURE_UNIT;
        rlSetUniform(rlGetLocationUniform(shader.id, "rblSceneDepth"), &unit, SHADER_UNIFORM_INT, 1);
    }
    // Receivers: sampler k reads texture unit RBL_SHADOW_TEXTURE_UNIT + k, and no light is shadowed
    // until a scene gives a map (an unbound sampler would read depth 0 and darken everything)
    for (int k = 0; k < d->shading.shadowMaps; k++)
    {
        char name[32];
        snprintf(name, sizeof(name), "rblShadowMap%i", k);
        int unit = RBL_SHADOW_TEXTURE_UNIT + k;
        rlSetUniform(rlGetLocationUniform(shader.id, name), &unit, SHADER_UNIFORM_INT, 1);
    }
    if (d->clustered)
    {
        int units[2] = { RBL_LIGHT_GRID_TEXTURE_UNIT, RBL_LIGHT_GRID_TEXTURE_UNIT + 1 };
        rlSetUniform(rlGetLocationUniform(shader.id, "rblLightData"), &units[0], SHADER_UNIFORM_INT, 1);
        rlSetUniform(rlGetLocationUniform(shader.id, "rblLightGrid"), &units[1], SHADER_UNIFORM_INT, 1);
    }
    for (int k = 0; d->shadowTransmittance && (k < d->shading.shadowMaps); k++)
    {
        char name[32];
        snprintf(name, sizeof(name), "rblShadowTint%i", k);
        int unit = RBL_SHADOW_TINT_TEXTURE_UNIT + k;
        rlSetUniform(rlGetLocationUniform(shader.id, name), &unit, SHADER_UNIFORM_INT, 1);
    }
    int none[4] = { -1, -1, -1, -1 };
    if (p->loc[RBL__U_SHADOW_LIGHT] != -1) rlSetUniform(p->loc[RBL__U_SHADOW_LIGHT], none, SHADER_UNIFORM_IVEC4, 1);
    rbl__markDrawn(p);
    float one = 1.0f, up[3] = { 0.0f, 1.0f, 0.0f };
    if (p->loc[RBL__U_EXPOSURE] != -1) rlSetUniform(p->loc[RBL__U_EXPOSURE], &one, SHADER_UNIFORM_FLOAT, 1);
    if (p->loc[RBL__U_AMBIENT_UP] != -1) rlSetUniform(p->loc[RBL__U_AMBIENT_UP], up, SHADER_UNIFORM_VEC3, 1);
    // A default Material's values (its zero fields), so raylib's DrawModel of such materials draws as
    // the header's own draws would
    if ((key->kind == RBL__KIND_LIT) || (key->kind == RBL__KIND_CASTER))
    {
        MaterialMap defaults[RBL__RAYLIB_MATERIAL_MAPS];
        Material none;
        memset(defaults, 0, sizeof(defaults));
        memset(&none, 0, sizeof(none));
        none.maps = defaults;
        rbl__applyMaterialValues(p, &none);
    }
    rlDisableShader();
    rbl__uploadScene(p);            // a program loaded mid-frame draws with the current scene
    return p;
}

// The header's own program for key (casters, passes): the registry's (one more holder) or a new
// compile; NULL (problem set) on failure
static rbl__Program *rbl__acquireProgram(const rbl__ProgramKey *key)
{
    for (int i = 0; i < rbl__state.programCount; i++)
    {
        rbl__Program *p = rbl__state.programs[i];
        if (memcmp(&p->key, key, sizeof(*key)) != 0) continue;
        p->refs++;
        return p;
    }
    return rbl__compileProgram(key);
}

// One holder fewer of a caster or pass; the last one deletes the program
static void rbl__releaseProgram(unsigned int id, int kind)
{
    for (int i = 0; i < rbl__state.programCount; i++)
    {
        rbl__Program *p = rbl__state.programs[i];
        if ((p->shader.id != id) || (p->key.kind != kind)) continue;
        if (--p->refs == 0)
        {
            if (rbl__glUsable()) rlUnloadShaderProgram(p->shader.id);
            rbl__removeProgram(p);
        }
        return;
    }
}

static void rbl__keyFromDesc(const RblLitShaderDesc *normalised, int kind, int pass, rbl__ProgramKey *key)
{
    memset(key, 0, sizeof(*key));
    key->desc = *normalised;
    key->kind = kind;
    key->pass = pass;
    key->shadowKinds = rbl__shadowKindsOf(NULL, 0, normalised->shading.shadowMaps);
}

// The receiver variant of program p (lit or G-buffer pass) for the scene's shadow maps: p itself
// when its compiled kinds match (or it samples no map), else the registry's variant, compiled on
// first need (a draw may stall for one compile when a scene first binds a new kind). On failure p,
// said once: p's upload leaves the maps of other kinds unsampled (rbl__uploadShadows)
static rbl__Program *rbl__shadowVariant(rbl__Program *p)
{
    if ((p == NULL) || (p->key.desc.shading.shadowMaps == 0) || (p->loc[RBL__U_SHADOW_PARAMS] == -1)) return p;
    rbl__Program *base = (p->shadowBase != NULL)? p->shadowBase : p;
    const rbl__Scene *s = &rbl__state.scene;
    int want = rbl__shadowKindsOf(s->shadowUniforms, s->shadowCount, base->key.desc.shading.shadowMaps);
    if (want == base->key.shadowKinds) return base;
    if ((base->shadowVariant != NULL) && (base->shadowVariant->key.shadowKinds == want)) return base->shadowVariant;
    rbl__Program *v = NULL;
    for (int i = 0; (i < rbl__state.programCount) && (v == NULL); i++)
        if ((rbl__state.programs[i]->shadowBase == base) && (rbl__state.programs[i]->key.shadowKinds == want)) v = rbl__state.programs[i];
    if (v == NULL)
    {
        rbl__ProgramKey key = base->key;
        key.shadowKinds = want;
        v = rbl__compileProgram(&key);
        if (v == NULL)
        {
            if (!base->shadowVariantNoted) TraceLog(LOG_WARNING, "RBL: program %u: the receiver variant for this scene's shadow map kinds failed (%s): maps of other kinds than its own left unsampled", base->shader.id, rbl__state.problem);
            base->shadowVariantNoted = true;
            return base;
        }
        v->shadowBase = base;
    }
    base->shadowVariant = v;
    return v;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: lit programs and per-draw material values   >>programs
//----------------------------------------------------------------------------------
Shader RblLoadLitShader(RblLitShaderDesc desc)
{
    Shader none;
    memset(&none, 0, sizeof(none));
    RblLitShaderDesc normalised;
    const char *bad = rbl__normaliseLitDesc(desc, &normalised);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadLitShader: %s", bad); return none; }
    if (desc.clustered && !desc.deferred && !normalised.clustered)
        TraceLog(LOG_INFO, "RBL: RblLoadLitShader: clustered lights need GLSL 3 (GL 3.3, ES 3, WebGL2); this context is %s: %i light slots (maxLights)", rbl__contextName(), normalised.maxLights);
    rbl__ProgramKey key;
    rbl__keyFromDesc(&normalised, RBL__KIND_LIT, 0, &key);
    rbl__Program *p = rbl__compileProgram(&key);
    if (p == NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadLitShader: %s", rbl__state.problem); return none; }
    // The holder's own copy of the locations (raylib's UnloadShader frees a Shader's locs: raylib's
    // allocator). An address a dead handle of this id had is skipped, so its stale copies stay stale.
    int *locs = NULL, *spare[8];
    int spares = 0;
    while (spares < 8)
    {
        locs = (int *)MemAlloc(RL_MAX_SHADER_LOCATIONS*sizeof(int));
        if ((locs == NULL) || !rbl__buried(p->shader.id, locs)) break;
        spare[spares++] = locs;
        locs = NULL;
    }
    for (int i = 0; i < spares; i++) MemFree(spare[i]);
    if (locs == NULL)
    {
        rlUnloadShaderProgram(p->shader.id);
        rbl__removeProgram(p);
        TraceLog(LOG_WARNING, "RBL: RblLoadLitShader: out of memory");
        return none;
    }
    memcpy(locs, p->shader.locs, RL_MAX_SHADER_LOCATIONS*sizeof(int));
    p->handleLocs = locs;
    Shader shader;
    shader.id = p->shader.id;
    shader.locs = locs;
    return shader;
}

bool RblIsLitShaderValid(Shader shader)
{
    rbl__Program *p = NULL;
    return (rbl__findLit(shader.id) != NULL) && (rbl__resolveShader(shader, &p) == NULL) && (p != NULL);
}

void RblUnloadLitShader(Shader *shader)
{
    if (shader == NULL) { TraceLog(LOG_WARNING, "RBL: RblUnloadLitShader: NULL shader"); return; }
    rbl__Program *p = NULL;
    const char *bad = rbl__resolveShader(*shader, &p);
    if ((bad == NULL) && (p == NULL))
    {
        // A lit program RblClose handed to its holder is a plain raylib Shader: released as
        // UnloadShader would (after CloseWindow its program went with the context)
        bool gl = rbl__glUsable();
        if (gl && (rlGetLocationUniform(shader->id, "rblAlphaCutoff") == -1)) bad = "not a lit program of this header";
        else
        {
            if (gl) rlUnloadShaderProgram(shader->id);
            MemFree(shader->locs);
            memset(shader, 0, sizeof(*shader));
            return;
        }
    }
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblUnloadLitShader: shader %u: %s", shader->id, bad); return; }
    // The locations array stays allocated (quarantine) until RblClose: no later allocation can take
    // its address while a stale copy holds it
    if (rbl__state.quarantineCount == rbl__state.quarantineCapacity)
    {
        int capacity = (rbl__state.quarantineCapacity > 0)? rbl__state.quarantineCapacity*2 : 16;
        int **q = (int **)RBL_REALLOC(rbl__state.quarantine, (size_t)capacity*sizeof(int *));
        if (q != NULL) { rbl__state.quarantine = q; rbl__state.quarantineCapacity = capacity; }
    }
    if (rbl__state.quarantineCount < rbl__state.quarantineCapacity) rbl__state.quarantine[rbl__state.quarantineCount++] = shader->locs;
    else MemFree(shader->locs);
    rbl__bury(p->shader.id, p->handleLocs);
    if (rbl__glUsable()) rlUnloadShaderProgram(p->shader.id);
    rbl__removeProgram(p);
    memset(shader, 0, sizeof(*shader));
    rbl__tidyAfterClose();
}

static bool rbl__lightFeatureOf(const RblLight *l, int *features)
{
    if ((l->type < RBL_LIGHT_POINT) || (l->type > RBL_LIGHT_SPOT) || (l->falloff < RBL_FALLOFF_WINDOWED) || (l->falloff > RBL_FALLOFF_CLASSIC)) return false;
    *features |= (l->type == RBL_LIGHT_POINT)? RBL_LIGHT_FEATURE_POINT : ((l->type == RBL_LIGHT_SPOT)? RBL_LIGHT_FEATURE_SPOT : RBL_LIGHT_FEATURE_DIRECTIONAL);
    if ((l->type != RBL_LIGHT_DIRECTIONAL) && (l->falloff == RBL_FALLOFF_CLASSIC)) *features |= RBL_LIGHT_FEATURE_CLASSIC_FALLOFF;
    return true;
}

int RblGetLightFeatures(const RblLight *lights, int count)
{
    int features = 0;
    if ((count < 0) || (count > RBL_MAX_SCENE_LIGHTS) || ((count > 0) && (lights == NULL)))
    {
        TraceLog(LOG_WARNING, "RBL: RblGetLightFeatures: count %i outside 0..RBL_MAX_SCENE_LIGHTS (%i) or lights NULL", count, RBL_MAX_SCENE_LIGHTS);
        return 0;
    }
    for (int i = 0; i < count; i++)
        if (!rbl__lightFeatureOf(&lights[i], &features)) { TraceLog(LOG_WARNING, "RBL: RblGetLightFeatures: light %i has an unknown type or falloff", i); return 0; }
    return features;
}

// The uniform values of one material for program p (zero fields take their defaults)
static void rbl__materialValues(const rbl__Program *p, const Material *material, rbl__MaterialValues *v)
{
    memset(v, 0, sizeof(*v));
    v->specularColor = WHITE;
    if (material->maps != NULL)
    {
        const MaterialMap *maps = material->maps;
        Color sc = maps[MATERIAL_MAP_SPECULAR].color;
        if ((sc.r | sc.g | sc.b | sc.a) != 0) v->specularColor = sc;
        v->emissiveColor = maps[MATERIAL_MAP_EMISSION].color;
        v->shininess = maps[MATERIAL_MAP_NORMAL].value;
        v->roughness = maps[MATERIAL_MAP_ROUGHNESS].value;
        v->metalness = maps[MATERIAL_MAP_METALNESS].value;
        v->emissive = maps[MATERIAL_MAP_EMISSION].value;
    }
    v->alphaCutoff = material->params[RBL_PARAM_ALPHA_CUTOFF];
    v->specular = material->params[RBL_PARAM_SPECULAR];
    // Defaults, and NaN/Inf or out-of-range values clamped to what the shaders accept
    bool specularMap = p->key.desc.material.specular;
    v->specular = !rbl__finite(v->specular)? 0.0f : v->specular;
    v->specular = (v->specular == 0.0f)? (specularMap? 1.0f : 0.5f) : ((v->specular < 0.0f)? 0.0f : v->specular);
    v->shininess = (!rbl__finite(v->shininess) || (v->shininess == 0.0f))? 32.0f : ((v->shininess < 1.0f)? 1.0f : v->shininess);
    v->roughness = (!rbl__finite(v->roughness) || (v->roughness == 0.0f))? 0.5f : ((v->roughness < 0.0f)? 0.0f : ((v->roughness > 1.0f)? 1.0f : v->roughness));
    v->metalness = !rbl__finite(v->metalness)? 0.0f : ((v->metalness < 0.0f)? 0.0f : ((v->metalness > 1.0f)? 1.0f : v->metalness));
    v->emissive = (!rbl__finite(v->emissive) || (v->emissive == 0.0f))? 1.0f : ((v->emissive < 0.0f)? 0.0f : v->emissive);
    v->alphaCutoff = !rbl__finite(v->alphaCutoff)? 0.5f : ((v->alphaCutoff == 0.0f)? 0.5f : v->alphaCutoff);
    v->alphaCeiling = 2.0f;         // no texel reaches it
    if (rbl__state.alphaBand.y > 0.0f)
    {
        // A hybrid batch's pass: solid texels (at or above the solid alpha), or the fringe below it
        if (rbl__state.alphaBand.x > 0.0f) v->alphaCutoff = rbl__state.alphaBand.x;
        v->alphaCeiling = rbl__state.alphaBand.y;
    }
    v->emissiveColor.a = 0;                         // only rgb matters
    if (p->key.desc.transmission)
    {
        float t = material->params[RBL_PARAM_TRANSMISSION];
        v->transmission = !rbl__finite(t)? 0.0f : ((t < 0.0f)? 0.0f : ((t > 1.0f)? 1.0f : t));
    }
    if (p->key.desc.relief && (material->maps != NULL))
    {
        float h = material->maps[MATERIAL_MAP_HEIGHT].value;
        Texture2D m = material->maps[MATERIAL_MAP_NORMAL].texture;
        v->relief[0] = (!rbl__finite(h) || (h == 0.0f))? 4.0f : ((h < 0.0f)? 0.0f : ((h > 65536.0f)? 65536.0f : h));
        v->relief[2] = (m.width > 0)? 1.0f/(float)m.width : 1.0f;
        v->relief[3] = (m.height > 0)? 1.0f/(float)m.height : 1.0f;
        if (m.id == 0) v->relief[0] = 0.0f;          // no material texture bound: no height to march
    }
}

// Upload the material's values into bound program p, unless the last draw with p used the same ones
static void rbl__applyMaterialValues(rbl__Program *p, const Material *material)
{
    rbl__MaterialValues v;
    rbl__materialValues(p, material, &v);
    if (p->valuesValid && (memcmp(&v, &p->values, sizeof(v)) == 0)) return;
    p->values = v;
    p->valuesValid = true;
    const int *loc = p->loc;
    if (loc[RBL__U_ALPHA_CUTOFF] != -1) { float band[2] = { v.alphaCutoff, v.alphaCeiling }; rlSetUniform(loc[RBL__U_ALPHA_CUTOFF], band, SHADER_UNIFORM_VEC2, 1); }
    if (loc[RBL__U_SPECULAR] != -1)
    {
        float s[4] = { rbl__colorToLinear(v.specularColor.r)*v.specular, rbl__colorToLinear(v.specularColor.g)*v.specular,
                       rbl__colorToLinear(v.specularColor.b)*v.specular, v.shininess };
        rlSetUniform(loc[RBL__U_SPECULAR], s, SHADER_UNIFORM_VEC4, 1);
    }
    if (loc[RBL__U_ROUGH_METAL] != -1) { float rm[2] = { v.roughness, v.metalness }; rlSetUniform(loc[RBL__U_ROUGH_METAL], rm, SHADER_UNIFORM_VEC2, 1); }
    if (loc[RBL__U_EMISSIVE_COLOR] != -1)
    {
        float e[3] = { rbl__colorToLinear(v.emissiveColor.r)*v.emissive, rbl__colorToLinear(v.emissiveColor.g)*v.emissive, rbl__colorToLinear(v.emissiveColor.b)*v.emissive };
        rlSetUniform(loc[RBL__U_EMISSIVE_COLOR], e, SHADER_UNIFORM_VEC3, 1);
    }
    if (loc[RBL__U_EMISSIVE_INTENSITY] != -1) rlSetUniform(loc[RBL__U_EMISSIVE_INTENSITY], &v.emissive, SHADER_UNIFORM_FLOAT, 1);
    if (loc[RBL__U_TRANSMISSION] != -1) rlSetUniform(loc[RBL__U_TRANSMISSION], &v.transmission, SHADER_UNIFORM_FLOAT, 1);
    if (loc[RBL__U_RELIEF] != -1) rlSetUniform(loc[RBL__U_RELIEF], v.relief, SHADER_UNIFORM_VEC4, 1);
}


// Why a material cannot draw in the current pass through a path; NULL = it can, with *program its
// lit program (NULL: the caller's own shader, drawn as raylib would). The shader is resolved before
// anything else of the Material is read (a stale copy's maps went with its program), then the maps:
// present, and every texture a draw binds still alive. No side effect: draws ask before touching state.
static const char *rbl__materialProblem(const Material *material, int path, rbl__Program **program)
{
    bool instanced = (path == RBL__PATH_INSTANCED);
    rbl__Program *p = NULL;
    *program = NULL;
    const char *bad = rbl__resolveShader(material->shader, &p);
    if (bad != NULL) return bad;
    if (material->maps == NULL) return "the material's maps are NULL (a zero Material?)";
    Texture2D t = material->maps[MATERIAL_MAP_ALBEDO].texture;
    if ((t.id != 0) && ((t.width <= 0) || (t.height <= 0) || (t.width > RBL__MAX_TEXTURE_SIDE) || (t.height > RBL__MAX_TEXTURE_SIDE)))
        return "the albedo texture's size is outside 1..65536";
    // Billboard paths bind albedo .. emission; raylib's DrawMesh every map with a texture
    int slots = ((path == RBL__PATH_MESH) || (path == RBL__PATH_SKINNED))? RBL__RAYLIB_MATERIAL_MAPS : MATERIAL_MAP_EMISSION + 1;
    for (int i = 0; i < slots; i++)
        if ((material->maps[i].texture.id != 0) && !rbl__glIsLive(RBL__GL_TEXTURE, material->maps[i].texture.id))
            return "a texture in the material's maps does not exist (unloaded?)";
    if (rbl__state.shadowPass != NULL) return NULL;        // every material casts through the header's casters
    const RblGBuffer *g = rbl__state.gbufferPass;
    if (p == NULL)
    {
        if (instanced) return "the material's shader is not an instanced lit program (RblLitShaderDesc.instanced)";
        if (g != NULL) return "inside a G-buffer pass the material's shader must be a deferred lit program";
        return NULL;        // the user's own shader: drawn as raylib would
    }
    if (p->key.desc.instanced != instanced) return instanced? "the material's program is not an instanced variant" : "an instanced variant draws only through RblDrawInstanced";
    if ((g != NULL) && !p->key.desc.deferred) return "a forward variant inside a G-buffer pass (RblLitShaderDesc.deferred)";
    if ((g != NULL) && (p->key.desc.shading.brdf != g->desc.shading.brdf)) return "the deferred variant's brdf differs from the G-buffer's";
    if ((g != NULL) && ((p->key.desc.transmission && !g->desc.transmission) || (p->key.desc.relief && !g->desc.relief)))
        return "a deferred transmission or relief variant in a G-buffer loaded without it (RblGBufferDesc.transmission, .relief)";
    if ((g == NULL) && p->key.desc.deferred) return "a deferred variant outside RblBeginGBuffer/RblEndGBuffer";
    // Without the bone attributes raylib's DrawMesh would enable them with no buffer (or defaults that
    // put every vertex on bone 0): a skinned program draws GPU-skinned meshes only
    if (p->key.desc.skinning && (path == RBL__PATH_BILLBOARD)) return "a skinned program (RblLitShaderDesc.skinning) draws only Models";
    if (p->key.desc.skinning && (path == RBL__PATH_MESH))
        return "a skinned program needs a GPU-skinned mesh (bone indices and weights uploaded, no CPU animVertices) of a Model with boneMatrices, drawn by RblDrawModel";
    *program = p;
    return NULL;
}

// Registry entry of the header's own program id of that kind (caster or pass), or NULL
static rbl__Program *rbl__findOwn(unsigned int id, int kind)
{
    for (int i = 0; (id != 0) && (i < rbl__state.programCount); i++)
        if ((rbl__state.programs[i]->shader.id == id) && (rbl__state.programs[i]->key.kind == kind)) return rbl__state.programs[i];
    return NULL;
}

static rbl__Program *rbl__findCaster(unsigned int id) { return rbl__findOwn(id, RBL__KIND_CASTER); }

// An on-demand caster (held in casterIds[slot], one holder, until the last shadow map goes) of desc's
// features and variant, compiled on first use; NULL (problem set) when it cannot be made
static rbl__Program *rbl__heldCaster(int slot, RblLitShaderDesc desc, int variant)
{
    rbl__Program *caster = rbl__findCaster(rbl__state.casterIds[slot]);
    if (caster != NULL) return caster;
    RblLitShaderDesc normalised;
    const char *bad = rbl__normaliseLitDesc(desc, &normalised);
    if (bad != NULL) { snprintf(rbl__state.problem, sizeof(rbl__state.problem), "%s", bad); return NULL; }
    rbl__ProgramKey key;
    rbl__keyFromDesc(&normalised, RBL__KIND_CASTER, variant, &key);
    caster = rbl__acquireProgram(&key);
    rbl__state.casterIds[slot] = (caster != NULL)? caster->shader.id : 0;
    return caster;
}

// The skinned caster: the first GPU-skinned mesh of a shadow pass
static rbl__Program *rbl__skinnedCaster(void)
{
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.skinning = true;
    return rbl__heldCaster(2, desc, 0);
}

// The cross-fade casters (vertex buffers, instanced): the first faded billboard of a shadow pass
static rbl__Program *rbl__fadeCaster(bool instanced)
{
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.crossFade = true; desc.instanced = instanced;
    return rbl__heldCaster(instanced? 4 : 3, desc, 0);
}

// The blended casters (vertex buffers, instanced): RblBeginShadowBlend's first draw
static rbl__Program *rbl__blendCaster(bool instanced)
{
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    desc.instanced = instanced;
    return rbl__heldCaster(instanced? 6 : 5, desc, 1);
}

// A shadowTransmittance program's per-draw inputs: map k's transmittance target on its unit (the
// default white texture where the scene's map has none: nothing tinted)
static void rbl__bindSceneTints(const rbl__Program *p)
{
    for (int k = 0; k < p->key.desc.shading.shadowMaps; k++)
    {
        unsigned int id = (k < rbl__state.scene.shadowCount)? rbl__state.scene.shadowTint[k] : 0;
        rlActiveTextureSlot(RBL_SHADOW_TINT_TEXTURE_UNIT + k);
        rlEnableTexture((id != 0)? id : rlGetTextureIdDefault());
    }
    rlActiveTextureSlot(0);
}

// A soft-particle program's per-draw depth inputs: the scene's depth texture on its unit, the current
// projection's depth row (as the fragment's own depth was made), its texel size and the material's
// fade distance
static void rbl__bindSoftDepth(const rbl__Program *p, const Material *material)
{
    rbl__Scene *sc = &rbl__state.scene;
    // No depth in the scene: the last RblEndSceneDepth's (the same size as the target drawn into)
    const bool captured = (sc->depth.id == 0) && rbl__state.capture.shown;
    if (captured) sc->depth = rbl__state.capture.target.depth;
    if ((sc->depth.id != 0) && !rbl__glIsLive(RBL__GL_TEXTURE, sc->depth.id))
    {
        if (!sc->depthNoted) TraceLog(LOG_WARNING, "RBL: the scene's depth texture %u was unloaded after RblSetScene: soft particles draw unsoftened until the next RblSetScene", sc->depth.id);
        sc->depthNoted = true;
        memset(&sc->depth, 0, sizeof(sc->depth));
    }
    Matrix proj = rlGetMatrixProjection();
    float fade = material->params[RBL_PARAM_SOFT_DISTANCE];
    if (!rbl__finite(fade) || (fade <= 0.0f)) fade = 0.5f;
    bool ortho = (proj.m3 == 0.0f) && (proj.m7 == 0.0f) && (proj.m11 == 0.0f) && (proj.m15 != 0.0f);
    float depth[4] = { proj.m10, proj.m14, (sc->depth.id == 0)? -1.0f : (ortho? 1.0f : 0.0f), fade };
    float texel[2] = { (sc->depth.width > 0)? 1.0f/(float)sc->depth.width : 1.0f, (sc->depth.height > 0)? 1.0f/(float)sc->depth.height : 1.0f };
    rlEnableShader(p->shader.id);
    rlSetUniform(p->loc[RBL__U_SOFT_DEPTH], depth, SHADER_UNIFORM_VEC4, 1);
    rlSetUniform(p->loc[RBL__U_SOFT_TEXEL], texel, SHADER_UNIFORM_VEC2, 1);
    if (sc->depth.id != 0) { rlActiveTextureSlot(RBL_SCENE_DEPTH_TEXTURE_UNIT); rlEnableTexture(sc->depth.id); rlActiveTextureSlot(0); }
    if (captured) memset(&sc->depth, 0, sizeof(sc->depth));
}

// The casters target's distance code (shadow_caster.fs.glsl) for a caster program in this shadow
// pass: perspective, near, far, log(far/near)
// The casters target's distance code (shadow_caster.fs.glsl): perspective, near, far, log(far/near)
static void rbl__casterDepth(const rbl__Program *caster)
{
    const rbl__ShadowMapState *st = rbl__state.shadowPass->state;
    bool perspective = (st->lightType != RBL_LIGHT_DIRECTIONAL);
    float depth[4] = { perspective? 1.0f : 0.0f, st->nearPlane, st->farPlane, perspective? logf(st->farPlane/st->nearPlane) : 1.0f };
    rlEnableShader(caster->shader.id);
    rlSetUniform(caster->loc[RBL__U_CASTER_DEPTH], depth, SHADER_UNIFORM_VEC4, 1);
}

static bool rbl__prepareDraw(Material *material, MaterialMap casterMaps[RBL__CASTER_MAPS], int path, bool fade, bool record, const char *fn, rbl__Program **program)
{
    const char *bad = rbl__materialProblem(material, path, program);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: %s: %s", fn, bad); return false; }
    if (rbl__state.shadowPass != NULL)
    {
        // Billboards with fade data cast the mixed cut-out (a crossFade caster); others the plain one;
        // blended casters (RblBeginShadowBlend) their coverage, the first frame's
        const rbl__ShadowMapState *pass = rbl__state.shadowPass->state;
        if (pass->blending && (path == RBL__PATH_SKINNED)) { TraceLog(LOG_WARNING, "RBL: %s: skinned Models cannot be blended casters (RblEndShadowBlend first)", fn); return false; }
        rbl__Program *caster = pass->blending? rbl__blendCaster(path == RBL__PATH_INSTANCED) : (path == RBL__PATH_SKINNED)? rbl__skinnedCaster() :
                               fade? rbl__fadeCaster(path == RBL__PATH_INSTANCED) : rbl__findCaster(rbl__state.casterIds[(path == RBL__PATH_INSTANCED)? 1 : 0]);
        if ((caster == NULL) && pass->blending) { TraceLog(LOG_WARNING, "RBL: %s: blended shadow caster unavailable (%s)", fn, rbl__state.problem); return false; }
        if ((caster == NULL) && (path == RBL__PATH_SKINNED)) { TraceLog(LOG_WARNING, "RBL: %s: skinned shadow caster unavailable (%s)", fn, rbl__state.problem); return false; }
        if ((caster == NULL) && fade) { TraceLog(LOG_WARNING, "RBL: %s: cross-fade shadow caster unavailable (%s)", fn, rbl__state.problem); return false; }
        if (caster == NULL) { TraceLog(LOG_WARNING, "RBL: %s: shadow caster program missing", fn); return false; }
        if (record && ((caster = rbl__recordVariant(caster)) == NULL)) { TraceLog(LOG_WARNING, "RBL: %s: batch-record caster unavailable (%s); not cast", fn, rbl__state.problem); return false; }
        rbl__casterDepth(caster);
        float tint = pass->coloured? 1.0f : 0.0f;
        if (caster->loc[RBL__U_CASTER_TINT] != -1) rlSetUniform(caster->loc[RBL__U_CASTER_TINT], &tint, SHADER_UNIFORM_FLOAT, 1);
        memset(casterMaps, 0, sizeof(MaterialMap)*RBL__CASTER_MAPS);
        casterMaps[MATERIAL_MAP_ALBEDO] = material->maps[MATERIAL_MAP_ALBEDO];
        material->maps = casterMaps;
        material->shader = caster->shader;
        *program = caster;
        return true;
    }
    if (*program == NULL) return true;
    rbl__checkRaylibDrew(*program);
    *program = rbl__shadowVariant(*program);    // the receiver compiled for the scene's map kinds
    if (record && ((*program = rbl__recordVariant(*program)) == NULL)) { TraceLog(LOG_WARNING, "RBL: %s: batch-record variant unavailable (%s); not drawn", fn, rbl__state.problem); return false; }
    material->shader = (*program)->shader;      // the registry's locations: a handle's are the caller's to free
    if (rbl__state.scene.shadowDropped && ((*program)->key.desc.shading.shadowMaps > 0)) rbl__noteDroppedShadow();
    if ((*program)->key.desc.softParticles) rbl__bindSoftDepth(*program, material);
    if ((*program)->key.desc.shadowTransmittance) rbl__bindSceneTints(*program);
    if ((*program)->key.desc.clustered) rbl__bindLightGrid();
    return true;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: the scene   >>scene
//----------------------------------------------------------------------------------
#define RBL__LIGHT_FLOATS 16            // position, colour, spot (vec4 each), falloff (vec3) + shadow map index + 1

// One light's uniform values (see lights.glsl); NULL when it is rejected, with the reason
static const char *rbl__packLight(const RblLight *l, float p[4], float c[4], float spot[4], float k[3])
{
    int features = 0;
    if (!rbl__lightFeatureOf(l, &features)) return "unknown type or falloff";
    if (!rbl__bounded3(l->position) || !rbl__finite3(l->direction)) return "NaN/Inf or |value| >= 1.15e18 in position, NaN/Inf direction";
    if (!rbl__finiteNonNegative(l->intensity) || !rbl__finiteNonNegative(l->range)) return "negative or non-finite intensity or range";
    if ((l->intensity > RBL_MAX_LIGHT_INTENSITY) || (l->range > 1.15e18f)) return "intensity above RBL_MAX_LIGHT_INTENSITY or range >= 1.15e18";
    bool directed = (l->type != RBL_LIGHT_POINT);
    // Scaled by the largest component first, so a long direction's squared length cannot overflow
    float dm = fmaxf(fabsf(l->direction.x), fmaxf(fabsf(l->direction.y), fabsf(l->direction.z)));
    float ds = (dm > 0.0f)? 1.0f/dm : 0.0f;
    Vector3 du = rbl__v3(l->direction.x*ds, l->direction.y*ds, l->direction.z*ds);
    float dl = sqrtf(du.x*du.x + du.y*du.y + du.z*du.z);
    if (directed && !(dm > 1e-30f)) return "zero direction";
    float outer = (l->outerAngle == 0.0f)? 30.0f : l->outerAngle;
    if ((l->type == RBL_LIGHT_SPOT) && (!rbl__finite(l->innerAngle) || !rbl__finite(outer) || (l->innerAngle < 0.0f) || (l->innerAngle > outer) || (outer > 90.0f)))
        return "spot angles must satisfy 0 <= inner <= outer <= 90 degrees";
    if (!rbl__finiteNonNegative(l->constant) || !rbl__finiteNonNegative(l->linear) || !rbl__finiteNonNegative(l->quadratic)) return "negative or non-finite attenuation coefficients";
    Vector3 d = du;
    float invDl = directed? 1.0f/dl : 0.0f;
    d.x *= invDl; d.y *= invDl; d.z *= invDl;
    if (l->type == RBL_LIGHT_DIRECTIONAL) { p[0] = -d.x; p[1] = -d.y; p[2] = -d.z; p[3] = 0.0f; }
    else { p[0] = l->position.x; p[1] = l->position.y; p[2] = l->position.z; p[3] = 1.0f; }
    c[0] = rbl__colorToLinear(l->color.r)*l->intensity;
    c[1] = rbl__colorToLinear(l->color.g)*l->intensity;
    c[2] = rbl__colorToLinear(l->color.b)*l->intensity;
    c[3] = ((l->type != RBL_LIGHT_DIRECTIONAL) && (l->range > 0.0f))? 1.0f/l->range : 0.0f;
    if (!rbl__finite(c[0]) || !rbl__finite(c[1]) || !rbl__finite(c[2]) || !rbl__finite(c[3])) return "intensity or 1/range overflows float";
    // Cone: t = saturate(cos(angle to axis)*scale + offset), 0 at the outer and 1 at the inner angle
    spot[0] = 0.0f; spot[1] = 0.0f; spot[2] = 0.0f; spot[3] = 1.0f;
    if (l->type == RBL_LIGHT_SPOT)
    {
        double cosInner = cos(l->innerAngle*PI/180.0), cosOuter = cos(outer*PI/180.0);
        double scale = 1.0/fmax(cosInner - cosOuter, 1e-4);
        spot[0] = (float)(d.x*scale); spot[1] = (float)(d.y*scale); spot[2] = (float)(d.z*scale); spot[3] = (float)(-cosOuter*scale);
    }
    k[0] = 0.0f; k[1] = 0.0f; k[2] = 1.0f;
    if ((l->type != RBL_LIGHT_DIRECTIONAL) && (l->falloff == RBL_FALLOFF_CLASSIC))
    {
        bool none = (l->constant == 0.0f) && (l->linear == 0.0f) && (l->quadratic == 0.0f);
        k[0] = none? 1.0f : l->constant; k[1] = none? 0.0f : l->linear; k[2] = none? 0.0f : l->quadratic;
    }
    else if (l->type == RBL_LIGHT_DIRECTIONAL) { k[0] = 1.0f; k[2] = 0.0f; }
    return NULL;
}

static void rbl__shadowUniformData(const RblShadowMap *map, float out[48]);
static const char *rbl__checkShadowMaps(const RblShadowMap *maps, int count, int lightCount);

// Bind the scene's shadow maps to their texture units (every receiver reads units 12 + k)
static void rbl__bindSceneShadows(void)
{
    for (int k = 0; k < rbl__state.scene.shadowCount; k++) { rlActiveTextureSlot(RBL_SHADOW_TEXTURE_UNIT + k); rlEnableTexture(rbl__state.scene.shadowTexture[k]); }
    rlActiveTextureSlot(0);
}

// A map the scene lists was unloaded: said once, at the first draw that would have sampled it
static void rbl__noteDroppedShadow(void)
{
    if (rbl__state.scene.shadowDroppedNoted) return;
    TraceLog(LOG_WARNING, "RBL: a shadow map of the scene was unloaded after RblSetScene: its light draws unshadowed until the next RblSetScene");
    rbl__state.scene.shadowDroppedNoted = true;
}

static int rbl__uploadSceneInto(rbl__Program *p);

// An unloaded shadow map leaves the scene at once, so no program samples its deleted texture; its
// light draws unshadowed (noted at the next draw that would have used it)
static void rbl__dropSceneShadow(unsigned int id)
{
    rbl__Scene *s = &rbl__state.scene;
    int k = 0;
    while ((k < s->shadowCount) && (s->shadowId[k] != id)) k++;
    if (k == s->shadowCount) return;
    for (int j = k; j + 1 < s->shadowCount; j++)
    {
        s->shadowLight[j] = s->shadowLight[j + 1]; s->shadowId[j] = s->shadowId[j + 1]; s->shadowTexture[j] = s->shadowTexture[j + 1]; s->shadowTint[j] = s->shadowTint[j + 1];
        memcpy(s->shadowUniforms[j], s->shadowUniforms[j + 1], sizeof(s->shadowUniforms[j]));
    }
    s->shadowCount--;
    for (int i = 0; i < s->lightCount; i++)
    {
        float *map = &s->lights[i*RBL__LIGHT_FLOATS + 15];      // shadow map index + 1
        if (*map == (float)(k + 1)) *map = 0.0f;
        else if (*map > (float)(k + 1)) *map -= 1.0f;
    }
    s->shadowDropped = true;
    s->shadowDroppedNoted = false;
    if (!rbl__glUsable()) return;
    rlActiveTextureSlot(RBL_SHADOW_TEXTURE_UNIT + s->shadowCount); rlDisableTexture();
    rbl__bindSceneShadows();
    for (int i = 0; i < rbl__state.programCount; i++) rbl__uploadSceneInto(rbl__state.programs[i]);
}

// Shadow uniforms of program p: map k shadows light slot slotOf[k] (-1 = none)
static void rbl__uploadShadows(const rbl__Program *p, const int slotOf[RBL_MAX_SHADOWS])
{
    const rbl__Scene *s = &rbl__state.scene;
    const int *loc = p->loc;
    int n = (s->shadowCount < p->key.desc.shading.shadowMaps)? s->shadowCount : p->key.desc.shading.shadowMaps;
    int lightOf[4] = { -1, -1, -1, -1 };
    // A map of another kind or format than the program compiled (raylib's DrawModel of a lit program,
    // a variant that failed) is left unsampled: its light draws unshadowed, never misread
    for (int k = 0; k < n; k++) lightOf[k] = (rbl__shadowCode(s->shadowUniforms[k][17]) == ((p->key.shadowKinds >> (4*k)) & 15))? slotOf[k] : -1;
    rlSetUniform(loc[RBL__U_SHADOW_LIGHT], lightOf, SHADER_UNIFORM_IVEC4, 1);
    if (n == 0) return;
    float rows[RBL_MAX_SHADOWS*16], params[RBL_MAX_SHADOWS*4], bias[RBL_MAX_SHADOWS*4], axes[RBL_MAX_SHADOWS*8], tiles[RBL_MAX_SHADOWS*16];
    for (int k = 0; k < n; k++)
    {
        memcpy(&rows[k*16], &s->shadowUniforms[k][0], 16*sizeof(float));
        memcpy(&params[k*4], &s->shadowUniforms[k][16], 4*sizeof(float));
        memcpy(&bias[k*4], &s->shadowUniforms[k][20], 4*sizeof(float));
        memcpy(&axes[k*8], &s->shadowUniforms[k][24], 8*sizeof(float));
        memcpy(&tiles[k*16], &s->shadowUniforms[k][32], 16*sizeof(float));
    }
    rlSetUniform(loc[RBL__U_SHADOW_MATRIX], rows, SHADER_UNIFORM_VEC4, 4*n);
    rlSetUniform(loc[RBL__U_SHADOW_PARAMS], params, SHADER_UNIFORM_VEC4, n);
    rlSetUniform(loc[RBL__U_SHADOW_BIAS], bias, SHADER_UNIFORM_VEC4, n);
    rlSetUniform(loc[RBL__U_SHADOW_AXES], axes, SHADER_UNIFORM_VEC4, 2*n);
    if (loc[RBL__U_SHADOW_TILES] != -1) rlSetUniform(loc[RBL__U_SHADOW_TILES], tiles, SHADER_UNIFORM_VEC4, 4*n);
}

// Ambient, fog and exposure of the scene, where the program declares them (the G-buffer's resolve
// takes the ambient of its geometry pass's scene at each resolve; lights go per draw there)
static void rbl__uploadSceneConstants(const rbl__Program *p)
{
    const rbl__Scene *s = &rbl__state.scene;
    const int *loc = p->loc;
    if (loc[RBL__U_AMBIENT] != -1) rlSetUniform(loc[RBL__U_AMBIENT], s->ambient, SHADER_UNIFORM_VEC3, 1);
    if (loc[RBL__U_AMBIENT_GROUND] != -1) rlSetUniform(loc[RBL__U_AMBIENT_GROUND], s->ground, SHADER_UNIFORM_VEC3, 1);
    if (loc[RBL__U_AMBIENT_UP] != -1) rlSetUniform(loc[RBL__U_AMBIENT_UP], s->up, SHADER_UNIFORM_VEC3, 1);
    if (loc[RBL__U_FOG] != -1)
    {
        // Another mode than the compiled one (or none) leaves the fog clear: density or slope 0
        bool same = (s->fogMode == p->key.desc.shading.fog);
        float f[4] = { s->fog[0], s->fog[1], s->fog[2], same? s->fog[3] : 0.0f }, start = same? s->fogStart : 0.0f;
        rlSetUniform(loc[RBL__U_FOG], f, SHADER_UNIFORM_VEC4, 1);
        rlSetUniform(loc[RBL__U_FOG_START], &start, SHADER_UNIFORM_FLOAT, 1);
    }
    if (loc[RBL__U_EXPOSURE] != -1) rlSetUniform(loc[RBL__U_EXPOSURE], &s->exposure, SHADER_UNIFORM_FLOAT, 1);
}

// ---- The light grid of clustered programs (light_grid.glsl) ----
// One world-space grid per scene, built on the CPU: uniform cells over the spheres of the bounded
// lights, each cell listing (in scene order, at most RBL_LIGHT_GRID_CELL_LIGHTS) the lights whose
// sphere touches it; unbounded lights, and lights whose range spans a quarter of the light set (they
// would list themselves in most cells), are listed once and lit everywhere. A world grid needs no
// camera: one build serves every view, target and pass of the frame.
#define RBL__GRID_WIDTH 2048            // Entries per row of the grid texture (light_grid.glsl: RBL_LIGHT_GRID_WIDTH)
#define RBL__GRID_DATA_LIGHTS 256       // Lights (4 texels each) per row of the light texture (RBL_LIGHT_DATA_LIGHTS)
typedef char rbl__gridFits[((long long)RBL_LIGHT_GRID_MAX_CELLS*(RBL_LIGHT_GRID_CELL_LIGHTS + 1) + RBL_MAX_SCENE_LIGHTS + 1 <= 2048LL*2048) &&
                           (RBL_MAX_SCENE_LIGHTS <= 2048*RBL__GRID_DATA_LIGHTS) && (RBL_LIGHT_GRID_MAX_CELLS >= 1) && (RBL_LIGHT_GRID_CELL_LIGHTS >= 1)? 1 : -1];

// array grown to hold n elements of size bytes (contents kept), or NULL (array untouched)
static void *rbl__gridGrow(void *array, int *capacity, int n, size_t size)
{
    if ((n <= *capacity) && (array != NULL)) return array;
    int c = (*capacity > 0)? *capacity : 1024;
    while (c < n) c *= 2;
    void *grown = RBL_REALLOC(array, (size_t)c*size);
    if (grown != NULL) *capacity = c;
    return grown;
}

// Texture *id (width x rows of format) holding data: made or remade taller when it has fewer rows
static bool rbl__gridTexture(unsigned int *id, int *held, int width, int rows, int format, const float *data)
{
    if ((*id != 0) && (rows > *held)) { rlUnloadTexture(*id); *id = 0; }
    if (*id == 0)
    {
        int alloc = 1;
        while (alloc < rows) alloc *= 2;                    // grows by doubling: a growing scene remakes it rarely
        *id = rlLoadTexture(NULL, width, alloc, format, 1);
        *held = (*id != 0)? alloc : 0;
        if (*id == 0) return false;
        // texelFetch only, but a float texture must be complete (no linear filter) to be read on ES 3
        rlTextureParameters(*id, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlTextureParameters(*id, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
    }
    rlUpdateTexture(*id, 0, 0, width, rows, format, data);
    return true;
}

// Cells [i0, i1] along axis a that a sphere (centre c, radius r) may touch, as floor() in the shader
// sees them within margin m
static void rbl__gridSpan(const rbl__LightGrid *g, int a, double c, double r, double m, int *i0, int *i1)
{
    double h = 1.0/(double)g->origin[3];
    double lo = floor((c - r - m - (double)g->origin[a])/h), hi = floor((c + r + m - (double)g->origin[a])/h);
    *i0 = (lo < 0.0)? 0 : ((lo > g->dims[a] - 1)? g->dims[a] - 1 : (int)lo);
    *i1 = (hi < 0.0)? 0 : ((hi > g->dims[a] - 1)? g->dims[a] - 1 : (int)hi);
}

// Counts (fill false) or lists (fill true) the cells each bounded light touches: a cell is a box
// widened by the margin the shader's float cell lookup needs, touched when the sphere reaches it
static void rbl__gridVisit(rbl__LightGrid *g, const rbl__Scene *s, bool fill, double margin)
{
    const double h = 1.0/(double)g->origin[3];
    const int unbounded = g->dims[3];
    for (int i = 0; i < s->lightCount; i++)
    {
        if (!g->bounded[i]) continue;
        const float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        const double c[3] = { d[0], d[1], d[2] }, r = 1.0/(double)d[7];
        int i0[3], i1[3];
        for (int a = 0; a < 3; a++) rbl__gridSpan(g, a, c[a], r, margin, &i0[a], &i1[a]);
        for (int z = i0[2]; z <= i1[2]; z++)
            for (int y = i0[1]; y <= i1[1]; y++)
                for (int x = i0[0]; x <= i1[0]; x++)
                {
                    const int cell[3] = { x, y, z };
                    double d2 = 0.0;
                    for (int a = 0; a < 3; a++)
                    {
                        double lo = (double)g->origin[a] + cell[a]*h - margin, hi = lo + h + 2.0*margin;
                        double e = (c[a] < lo)? lo - c[a] : ((c[a] > hi)? c[a] - hi : 0.0);
                        d2 += e*e;
                    }
                    if (d2 > r*r) continue;
                    int k = (z*g->dims[1] + y)*g->dims[0] + x;
                    if (!fill) { g->counts[k]++; continue; }
                    int start = (int)g->list[unbounded + k], end = (int)g->list[unbounded + k + 1];
                    if (start + g->counts[k] < end) g->list[start + g->counts[k]++] = (float)i;
                }
    }
}

// Builds the grid of the current scene and uploads it (GL needed); on failure (memory, float textures)
// the grid is empty: clustered programs light nothing but the ambient, said once
static void rbl__buildLightGrid(void)
{
    rbl__Scene *s = &rbl__state.scene;
    rbl__LightGrid *g = &s->grid;
    const int n = s->lightCount, cap = RBL_LIGHT_GRID_CELL_LIGHTS;
    g->dirty = false;
    g->builds++;
    memset(g->origin, 0, sizeof(g->origin)); memset(g->dims, 0, sizeof(g->dims));
    g->cellSize = 0.0f; g->entries = g->fullestCell = g->cappedCells = 0;
    const int dataRows = (n > 0)? (n + RBL__GRID_DATA_LIGHTS - 1)/RBL__GRID_DATA_LIGHTS : 1;
    void *grown = rbl__gridGrow(g->data, &g->dataCapacity, dataRows*RBL__GRID_DATA_LIGHTS*16, sizeof(float));
    if (grown != NULL) g->data = (float *)grown;
    grown = (grown != NULL)? rbl__gridGrow(g->bounded, &g->boundedCapacity, (n > 0)? n : 1, 1) : NULL;
    if (grown != NULL) g->bounded = (unsigned char *)grown;
    if (grown == NULL) { TraceLog(LOG_WARNING, "RBL: RblSetScene: out of memory for the light grid: clustered programs light none of %i lights", n); return; }
    // The light texture (scene order) and which lights the cells list
    double lo[3] = { 0.0, 0.0, 0.0 }, hi[3] = { 0.0, 0.0, 0.0 };
    int listed = 0;
    memset(g->data, 0, (size_t)dataRows*RBL__GRID_DATA_LIGHTS*16*sizeof(float));
    for (int i = 0; i < n; i++)
    {
        const float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        float *t = &g->data[i*16];
        t[0] = d[0]; t[1] = d[1]; t[2] = d[2]; t[3] = (float)s->lightFeatures[i];
        memcpy(&t[4], &d[4], 8*sizeof(float));
        t[12] = d[12]; t[13] = d[13]; t[14] = d[14];
        g->bounded[i] = (d[3] != 0.0f) && (d[7] > 0.0f);
        for (int a = 0; (a < 3) && g->bounded[i]; a++)
        {
            lo[a] = (listed == 0)? d[a] : fmin(lo[a], d[a]);
            hi[a] = (listed == 0)? d[a] : fmax(hi[a], d[a]);
        }
        listed += g->bounded[i];
    }
    double extent = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2])), radii = 0.0, far = 0.0;
    int unbounded = 0;
    listed = 0;
    for (int i = 0; i < n; i++)
    {
        const float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        if (g->bounded[i] && (1.0/(double)d[7] > 0.25*extent)) g->bounded[i] = 0;
        if (!g->bounded[i]) { unbounded++; continue; }
        double r = 1.0/(double)d[7];
        for (int a = 0; a < 3; a++)
        {
            lo[a] = (listed == 0)? d[a] - r : fmin(lo[a], d[a] - r);
            hi[a] = (listed == 0)? d[a] + r : fmax(hi[a], d[a] + r);
            far = fmax(far, fabs((double)d[a]) + r);
        }
        radii += r;
        listed++;
    }
    // Cells about the lights' mean radius, fewer when the box would need more than the maximum; where
    // a cell is reached by more lights than it lists, smaller cells (up to 3 times) while they fit
    const double ext[3] = { hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] };
    double h = (listed > 0)? fmax(0.75*radii/listed, cbrt(ext[0]*ext[1]*ext[2]/RBL_LIGHT_GRID_MAX_CELLS)) : 1.0;
    for (;;)
    {
        double cells = 1.0;
        for (int a = 0; a < 3; a++) cells *= fmax(1.0, ceil(ext[a]/h));
        if (cells <= RBL_LIGHT_GRID_MAX_CELLS) break;
        h *= 1.0625;
    }
    int cells = 0;
    long total = 0;
    for (int attempt = 0; ; attempt++)
    {
        if (listed > 0)
        {
            for (int a = 0; a < 3; a++) { g->dims[a] = (int)fmax(1.0, ceil(ext[a]/h)); g->origin[a] = (float)lo[a]; }
            g->origin[3] = (float)(1.0/h);
            g->cellSize = (float)h;
        }
        cells = g->dims[0]*g->dims[1]*g->dims[2];
        g->dims[3] = unbounded;
        g->fullestCell = g->cappedCells = 0;
        grown = rbl__gridGrow(g->counts, &g->countCapacity, (cells > 0)? cells : 1, sizeof(int));
        if (grown == NULL) break;
        g->counts = (int *)grown;
        const double margin = 0.01*h + 1e-6*(far + fabs(lo[0]) + fabs(lo[1]) + fabs(lo[2]));
        memset(g->counts, 0, (size_t)((cells > 0)? cells : 1)*sizeof(int));
        if (cells > 0) rbl__gridVisit(g, s, false, margin);
        total = unbounded + ((cells > 0)? cells + 1 : 1);
        for (int k = 0; k < cells; k++)
        {
            if (g->counts[k] > g->fullestCell) g->fullestCell = g->counts[k];
            if (g->counts[k] > cap) g->cappedCells++;
            total += (g->counts[k] < cap)? g->counts[k] : cap;
        }
        double finer = 1.0;
        for (int a = 0; a < 3; a++) finer *= fmax(1.0, ceil(ext[a]*1.5/h));
        if ((g->cappedCells == 0) || (attempt == 3) || (finer > RBL_LIGHT_GRID_MAX_CELLS)) break;
        h /= 1.5;
    }
    const int listRows = (int)((total + RBL__GRID_WIDTH - 1)/RBL__GRID_WIDTH);
    const double margin = 0.01*h + 1e-6*(far + fabs(lo[0]) + fabs(lo[1]) + fabs(lo[2]));
    grown = (grown != NULL)? rbl__gridGrow(g->list, &g->listCapacity, listRows*RBL__GRID_WIDTH, sizeof(float)) : NULL;
    if (grown == NULL) { TraceLog(LOG_WARNING, "RBL: RblSetScene: out of memory for the light grid: clustered programs light none of %i lights", n); memset(g->dims, 0, sizeof(g->dims)); return; }
    g->list = (float *)grown;
    memset(g->list, 0, (size_t)listRows*RBL__GRID_WIDTH*sizeof(float));
    for (int i = 0, u = 0; i < n; i++) if (!g->bounded[i]) g->list[u++] = (float)i;
    long at = unbounded + cells + 1;
    for (int k = 0; k < cells; k++)
    {
        g->list[unbounded + k] = (float)at;
        at += (g->counts[k] < cap)? g->counts[k] : cap;
        g->counts[k] = 0;
    }
    if (cells > 0) { g->list[unbounded + cells] = (float)at; rbl__gridVisit(g, s, true, margin); }
    g->entries = (cells > 0)? (int)(at - unbounded - cells - 1) : 0;
    if ((g->cappedCells > 0) && !g->capNoted)
        TraceLog(LOG_WARNING, "RBL: RblSetScene: %i light grid cells are reached by more than RBL_LIGHT_GRID_CELL_LIGHTS (%i) lights (up to %i): each lists the scene's first %i, the others stay unlit there",
                 g->cappedCells, cap, g->fullestCell, cap);
    g->capNoted = (g->cappedCells > 0);
    if (!rbl__gridTexture(&g->dataId, &g->dataRows, RBL__GRID_DATA_LIGHTS*4, dataRows, RL_PIXELFORMAT_UNCOMPRESSED_R32G32B32A32, g->data) ||
        !rbl__gridTexture(&g->listId, &g->listRows, RBL__GRID_WIDTH, listRows, RL_PIXELFORMAT_UNCOMPRESSED_R32, g->list))
    {
        TraceLog(LOG_WARNING, "RBL: RblSetScene: the light grid's float textures could not be made: clustered programs light none of %i lights", n);
        memset(g->dims, 0, sizeof(g->dims));
    }
}

// The grid's textures on their units (every clustered draw: other code may have bound those units)
static void rbl__bindLightGrid(void)
{
    const rbl__LightGrid *g = &rbl__state.scene.grid;
    rlActiveTextureSlot(RBL_LIGHT_GRID_TEXTURE_UNIT); rlEnableTexture((g->dataId != 0)? g->dataId : rlGetTextureIdDefault());
    rlActiveTextureSlot(RBL_LIGHT_GRID_TEXTURE_UNIT + 1); rlEnableTexture((g->listId != 0)? g->listId : rlGetTextureIdDefault());
    rlActiveTextureSlot(0);
}

// The grid into clustered program p (bound): built first when the scene changed; returns lights of
// types p does not compile (left out, as the slots leave them out)
static int rbl__uploadSceneGrid(const rbl__Program *p)
{
    rbl__Scene *s = &rbl__state.scene;
    rbl__LightGrid *g = &s->grid;
    if (g->dirty)
    {
        rbl__buildLightGrid();
        rbl__bindLightGrid();
    }
    rlSetUniform(p->loc[RBL__U_GRID_ORIGIN], g->origin, SHADER_UNIFORM_VEC4, 1);
    rlSetUniform(p->loc[RBL__U_GRID_DIMS], g->dims, SHADER_UNIFORM_IVEC4, 1);
    int slotOf[RBL_MAX_SHADOWS] = { -1, -1, -1, -1 };
    int skipped = 0;
    for (int i = 0; i < s->lightCount; i++)
    {
        const float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        if ((s->lightFeatures[i] & ~p->key.desc.shading.lightFeatures & ~RBL_LIGHT_FEATURE_POINT) != 0) { skipped++; continue; }
        if (d[15] > 0.0f) slotOf[(int)d[15] - 1] = i;
    }
    if (p->loc[RBL__U_SHADOW_MATRIX] != -1) rbl__uploadShadows(p, slotOf);
    return skipped;
}

static void rbl__freeLightGrid(rbl__LightGrid *g)
{
    if (rbl__glUsable())
    {
        if (g->dataId != 0) rlUnloadTexture(g->dataId);
        if (g->listId != 0) rlUnloadTexture(g->listId);
    }
    RBL_FREE(g->data); RBL_FREE(g->list); RBL_FREE(g->counts); RBL_FREE(g->bounded);
    memset(g, 0, sizeof(*g));
}

#if defined(RBL_INSTRUMENTS)
RblLightGridStats RblGetLightGridStats(void)
{
    const rbl__LightGrid *g = &rbl__state.scene.grid;
    RblLightGridStats out;
    memset(&out, 0, sizeof(out));
    for (int a = 0; a < 3; a++) out.cells[a] = g->dims[a];
    out.cellSize = g->cellSize;
    out.origin = rbl__v3(g->origin[0], g->origin[1], g->origin[2]);
    out.unbounded = g->dims[3];
    out.entries = g->entries;
    out.fullestCell = g->fullestCell;
    out.cappedCells = g->cappedCells;
    out.builds = g->builds;
    return out;
}
#endif

// The scene into one forward program: its first maxLights lights of compiled types, ambient, fog,
// exposure and the shadow maps it receives; returns lights left out (no slot or type not compiled)
static int rbl__uploadSceneLights(const rbl__Program *p)
{
    const rbl__Scene *s = &rbl__state.scene;
    const int *loc = p->loc;
    float pos[RBL_MAX_LIGHTS*4], col[RBL_MAX_LIGHTS*4], spot[RBL_MAX_LIGHTS*4], att[RBL_MAX_LIGHTS*3];
    int slotOf[RBL_MAX_SHADOWS] = { -1, -1, -1, -1 };
    int n = 0, skipped = 0;
    for (int i = 0; i < s->lightCount; i++)
    {
        const float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        if ((n == p->key.desc.maxLights) || ((s->lightFeatures[i] & ~p->key.desc.shading.lightFeatures & ~RBL_LIGHT_FEATURE_POINT) != 0)) { skipped++; continue; }
        memcpy(&pos[n*4], &d[0], 4*sizeof(float)); memcpy(&col[n*4], &d[4], 4*sizeof(float));
        memcpy(&spot[n*4], &d[8], 4*sizeof(float)); memcpy(&att[n*3], &d[12], 3*sizeof(float));
        if (d[15] > 0.0f) slotOf[(int)d[15] - 1] = n;
        n++;
    }
    rlSetUniform(loc[RBL__U_LIGHT_COUNT], &n, SHADER_UNIFORM_INT, 1);
    if (n > 0)
    {
        rlSetUniform(loc[RBL__U_LIGHT_POSITION], pos, SHADER_UNIFORM_VEC4, n);
        rlSetUniform(loc[RBL__U_LIGHT_COLOR], col, SHADER_UNIFORM_VEC4, n);
        if (loc[RBL__U_LIGHT_SPOT] != -1) rlSetUniform(loc[RBL__U_LIGHT_SPOT], spot, SHADER_UNIFORM_VEC4, n);
        if (loc[RBL__U_LIGHT_ATTENUATION] != -1) rlSetUniform(loc[RBL__U_LIGHT_ATTENUATION], att, SHADER_UNIFORM_VEC3, n);
    }
    if (loc[RBL__U_SHADOW_PARAMS] != -1) rbl__uploadShadows(p, slotOf);
    return skipped;
}

// The current scene into program p (every kind reads what it declares); returns lights left out
static int rbl__uploadSceneInto(rbl__Program *p)
{
    if ((p->loc[RBL__U_LIGHT_COUNT] == -1) && (p->loc[RBL__U_GRID_DIMS] == -1) && (p->loc[RBL__U_FOG] == -1) && (p->loc[RBL__U_EXPOSURE] == -1) && (p->loc[RBL__U_SHADOW_PARAMS] == -1) && (p->loc[RBL__U_AMBIENT] == -1)) return 0;
    int skipped = 0;
    rlEnableShader(p->shader.id);
    bool pass = (p->key.kind == RBL__KIND_PASS);
    rbl__uploadSceneConstants(p);
    if (!pass && (p->loc[RBL__U_LIGHT_COUNT] != -1)) skipped = rbl__uploadSceneLights(p);
    else if (!pass && (p->loc[RBL__U_GRID_DIMS] != -1)) skipped = rbl__uploadSceneGrid(p);
    rlDisableShader();
    return skipped;
}

static void rbl__uploadScene(rbl__Program *p) { rbl__uploadSceneInto(p); }

bool RblSetScene(const RblScene *scene)
{
    const char *bad = NULL;
    int badLight = -1;
    Vector3 up = rbl__v3(0.0f, 1.0f, 0.0f);
    if (scene == NULL) bad = "NULL scene";
    else if ((scene->lightCount < 0) || ((scene->lightCount > 0) && (scene->lights == NULL))) bad = "lightCount negative, or lights NULL";
    else if (scene->lightCount > RBL_MAX_SCENE_LIGHTS) bad = "more than RBL_MAX_SCENE_LIGHTS lights";
    else if ((scene->fog.mode < RBL_FOG_NONE) || (scene->fog.mode > RBL_FOG_EXP2)) bad = "unknown fog.mode";
    else if ((scene->fog.mode != RBL_FOG_NONE) && (!rbl__finite(scene->fog.start) || !rbl__finite(scene->fog.end) || !rbl__finiteNonNegative(scene->fog.density)))
        bad = "fog start/end not finite or density negative";
    else if ((scene->fog.mode == RBL_FOG_LINEAR) && !(scene->fog.end > scene->fog.start)) bad = "linear fog needs end > start";
    else if (!rbl__finiteNonNegative(scene->exposure)) bad = "exposure negative or not finite";
    else if (!rbl__finite3(scene->ambientUp) || ((rbl__len2(scene->ambientUp) != 0.0f) && !rbl__normalizeTo(scene->ambientUp, &up))) bad = "ambientUp not a finite direction";
    else if ((scene->depth.id != 0) && ((scene->depth.width <= 0) || (scene->depth.height <= 0) || (scene->depth.width > RBL_MAX_TARGET_SIZE) || (scene->depth.height > RBL_MAX_TARGET_SIZE)))
        bad = "depth texture size outside 1..RBL_MAX_TARGET_SIZE";
    else if ((scene->depth.id != 0) && !rbl__glIsLive(RBL__GL_TEXTURE, scene->depth.id)) bad = "the depth texture does not exist (unloaded?)";
    else bad = rbl__checkShadowMaps(scene->shadowMaps, scene->shadowMapCount, scene->lightCount);
    rbl__Scene *s = &rbl__state.scene;
    // Packed storage grows to the largest scene (no allocation in a steady frame)
    if ((bad == NULL) && (scene->lightCount > s->lightCapacity))
    {
        int capacity = (s->lightCapacity > 0)? s->lightCapacity : 16;
        while (capacity < scene->lightCount) capacity *= 2;
        float *lights = (float *)RBL_MALLOC((size_t)capacity*RBL__LIGHT_FLOATS*sizeof(float));
        float *staging = (float *)RBL_MALLOC((size_t)capacity*RBL__LIGHT_FLOATS*sizeof(float));
        int *features = (int *)RBL_MALLOC((size_t)capacity*sizeof(int));
        if ((lights == NULL) || (staging == NULL) || (features == NULL))
        {
            RBL_FREE(lights); RBL_FREE(staging); RBL_FREE(features);
            bad = "out of memory for the lights";
        }
        else
        {
            if (s->lightCount > 0)
            {
                memcpy(lights, s->lights, (size_t)s->lightCount*RBL__LIGHT_FLOATS*sizeof(float));
                memcpy(features, s->lightFeatures, (size_t)s->lightCount*sizeof(int));
            }
            RBL_FREE(s->lights); RBL_FREE(s->staging); RBL_FREE(s->lightFeatures);
            s->lights = lights; s->staging = staging; s->lightFeatures = features;
            s->lightCapacity = capacity;
        }
    }
    // Validate every light into the staging area first: a rejected scene changes nothing
    for (int i = 0; (bad == NULL) && (i < scene->lightCount); i++)
    {
        float *d = &s->staging[i*RBL__LIGHT_FLOATS];
        bad = rbl__packLight(&scene->lights[i], &d[0], &d[4], &d[8], &d[12]);
        if (bad != NULL) badLight = i;
    }
    if (bad != NULL)
    {
        if (badLight >= 0) TraceLog(LOG_WARNING, "RBL: RblSetScene: light %i rejected: %s", badLight, bad);
        else TraceLog(LOG_WARNING, "RBL: RblSetScene: %s", bad);
        return false;
    }
    for (int i = 0; i < scene->lightCount; i++)
    {
        float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        memcpy(d, &s->staging[i*RBL__LIGHT_FLOATS], RBL__LIGHT_FLOATS*sizeof(float));
        d[15] = 0.0f;
        s->lightFeatures[i] = 0;
        rbl__lightFeatureOf(&scene->lights[i], &s->lightFeatures[i]);
    }
    s->lightCount = scene->lightCount;
    Color sky = scene->ambient, ground = scene->ambientGround;
    if ((ground.r | ground.g | ground.b | ground.a) == 0) ground = sky;       // flat
    s->ambient[0] = rbl__colorToLinear(sky.r); s->ambient[1] = rbl__colorToLinear(sky.g); s->ambient[2] = rbl__colorToLinear(sky.b);
    s->ground[0] = rbl__colorToLinear(ground.r); s->ground[1] = rbl__colorToLinear(ground.g); s->ground[2] = rbl__colorToLinear(ground.b);
    s->up[0] = up.x; s->up[1] = up.y; s->up[2] = up.z;
    const RblFog *fog = &scene->fog;
    s->fogMode = fog->mode;
    s->fog[0] = rbl__colorToLinear(fog->color.r); s->fog[1] = rbl__colorToLinear(fog->color.g); s->fog[2] = rbl__colorToLinear(fog->color.b);
    s->fog[3] = (fog->mode == RBL_FOG_NONE)? 0.0f : ((fog->mode == RBL_FOG_LINEAR)? 1.0f/(fog->end - fog->start) : fog->density);
    s->fogStart = (fog->mode == RBL_FOG_NONE)? 0.0f : fog->start;
    s->exposure = (scene->exposure == 0.0f)? 1.0f : scene->exposure;
    s->depth = scene->depth;
    s->depthNoted = false;
    s->shadowCount = scene->shadowMapCount;
    s->shadowDropped = s->shadowDroppedNoted = false;
    for (int k = 0; k < scene->shadowMapCount; k++)
    {
        const RblShadowMap *map = &scene->shadowMaps[k];
        rbl__shadowUniformData(map, s->shadowUniforms[k]);
        s->shadowLight[k] = map->light;
        s->shadowId[k] = map->id;
        s->shadowTexture[k] = (map->casters.id != 0)? map->casters.id : map->depth.id;
        s->shadowTint[k] = map->transmittance.id;
        s->lights[map->light*RBL__LIGHT_FLOATS + 15] = (float)(k + 1);
    }
    rbl__bindSceneShadows();
    s->grid.dirty = true;           // built by the first clustered program's upload (none: never)
    // Every live program now, so raylib's DrawModel/DrawMesh (which bind programs themselves) see it too
    for (int i = 0; i < rbl__state.programCount; i++)
    {
        rbl__Program *p = rbl__state.programs[i];
        if (!rbl__programAlive(p)) { rbl__forgetProgram(p); i--; continue; }
        rbl__checkRaylibDrew(p);
        int skipped = rbl__uploadSceneInto(p);
        if ((skipped > 0) && p->key.desc.clustered)
            TraceLog(LOG_INFO, "RBL: RblSetScene: clustered lit program %u lights %i of %i lights (types not in lightFeatures)", p->shader.id, s->lightCount - skipped, s->lightCount);
        else if (skipped > 0)
            TraceLog(LOG_INFO, "RBL: RblSetScene: lit program %u lights %i of %i lights (maxLights %i, or types not in lightFeatures)",
                     p->shader.id, s->lightCount - skipped, s->lightCount, p->key.desc.maxLights);
    }
    return true;
}

// Draw a mesh with the material's lit values (or as a caster inside a shadow pass) through raylib
// Why a mesh cannot be drawn with this transform; NULL = it can
static const char *rbl__meshProblem(const Mesh *mesh, const Matrix *transform)
{
    // GL 3 / ES 3 draw through the mesh's vertex array (a core context has no other way): it must be
    // a live one (UnloadMesh deletes it), which also vouches for the mesh's arrays read next
    if (rbl__glsl() >= 300)
    {
        if (mesh->vaoId == 0) return "mesh has no vertex array (vaoId 0: not uploaded, or unloaded)";
        if (!rbl__glIsLive(RBL__GL_VERTEX_ARRAY, mesh->vaoId)) return "mesh's vertex array does not exist (unloaded?)";
    }
    if ((mesh->vertexCount <= 0) || ((mesh->vaoId == 0) && ((mesh->vboId == NULL) || (mesh->vboId[0] == 0)))) return "mesh not uploaded (no vertices, vaoId and vboId 0)";
    if (!rbl__exponentsBelow(transform, 16, RBL__BILLBOARD_LIMIT_EXPONENT)) return "transform with NaN/Inf or |value| >= 2^60";
    return NULL;
}

// Whether raylib skins this mesh on the GPU: bone indices and weights in raylib's bone buffers (only
// a SUPPORT_GPU_SKINNING build has those vboId slots) and positions not already skinned on the CPU
static bool rbl__meshGpuSkinned(const Mesh *mesh)
{
#if RBL_GPU_SKINNING
    return (mesh->boneIndices != NULL) && (mesh->boneWeights != NULL) && (mesh->animVertices == NULL) && (mesh->vboId != NULL) &&
           (mesh->vboId[RL_DEFAULT_SHADER_ATTRIB_LOCATION_BONEINDICES] != 0) && (mesh->vboId[RL_DEFAULT_SHADER_ATTRIB_LOCATION_BONEWEIGHTS] != 0);
#else
    (void)mesh;
    return false;
#endif
}

// Why a Model's bone matrices cannot be uploaded; NULL = they can
static const char *rbl__bonesProblem(const Model *model)
{
    const long long boneCount = (long long)model->skeleton.boneCount;   // int in raylib 6.0, unsigned int in 6.1
    if ((boneCount < 1) || (boneCount > RBL_MAX_BONES)) return "skeleton.boneCount outside 1..RBL_MAX_BONES";
    for (int b = 0; b < (int)boneCount; b++)
        if (!rbl__exponentsBelow(&model->boneMatrices[b], 16, RBL__BILLBOARD_LIMIT_EXPONENT)) return "a bone matrix with NaN/Inf or |value| >= 2^60";
    return NULL;
}

// A Model's bone matrices into a mat4 array uniform. raylib 6.0's rlSetUniformMatrices transposes
// on desktop GL and not on ES/WebGL: ES gets the matrices transposed first, so both arrive as set
static void rbl__uploadBones(int loc, const Model *bones)
{
    int n = (int)bones->skeleton.boneCount;                 // checked to 1..RBL_MAX_BONES
    if ((rbl__glsl() != 300) && (rbl__glsl() != 100)) { rlSetUniformMatrices(loc, bones->boneMatrices, n); return; }
    for (int b = 0; b < n; b++)
    {
        const Matrix *m = &bones->boneMatrices[b];
        // Positional: Matrix declares m0 m4 m8 m12 m1 ..., so field by field this is the transpose
        Matrix t = { m->m0, m->m1, m->m2, m->m3, m->m4, m->m5, m->m6, m->m7, m->m8, m->m9, m->m10, m->m11, m->m12, m->m13, m->m14, m->m15 };
        rbl__state.boneScratch[b] = t;
    }
    rlSetUniformMatrices(loc, rbl__state.boneScratch, n);
}

// DrawMesh with the lit values of a checked material; bones: the Model's matrices for a skinned draw
static void rbl__drawMesh(Mesh mesh, Material material, Matrix transform, int path, const Model *bones)
{
    MaterialMap casterMaps[RBL__CASTER_MAPS];
    rbl__Program *p = NULL;
    if (!rbl__prepareDraw(&material, casterMaps, path, false, false, (bones != NULL)? "RblDrawModel" : "RblDrawMesh", &p)) return;
    if (p != NULL)
    {
        rlEnableShader(material.shader.id);
        rbl__applyMaterialValues(p, &material);
        // As raylib's DrawModel does for its own skinning shaders (DrawMesh alone uploads no bones)
        int loc = p->shader.locs[SHADER_LOC_MATRIX_BONETRANSFORMS];
        if (p->key.desc.skinning && (path == RBL__PATH_SKINNED) && (loc != -1)) rbl__uploadBones(loc, bones);
    }
    else if ((path == RBL__PATH_SKINNED) && (material.shader.locs != NULL) && (material.shader.locs[SHADER_LOC_MATRIX_BONETRANSFORMS] != -1))
    {
        rlEnableShader(material.shader.id);     // the user's own skinning shader, as raylib's DrawModel feeds it
        rbl__uploadBones(material.shader.locs[SHADER_LOC_MATRIX_BONETRANSFORMS], bones);
    }
    DrawMesh(mesh, material, transform);
    if (p != NULL) { rlEnableShader(p->shader.id); rbl__markDrawn(p); rlDisableShader(); }
}

void RblDrawMesh(Mesh mesh, Material material, Matrix transform)
{
    rbl__Program *p = NULL;
    const char *bad = rbl__meshProblem(&mesh, &transform);
    if (bad == NULL) bad = rbl__materialProblem(&material, RBL__PATH_MESH, &p);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawMesh: %s", bad); return; }
    rbl__drawMesh(mesh, material, transform, RBL__PATH_MESH, NULL);
}

void RblDrawModel(Model model, Vector3 position, float scale, Color tint)
{
    // Every mesh and material is checked first: a model draws whole or not at all
    const char *bad = NULL;
    int at = -1;
    if ((model.meshes == NULL) || (model.materials == NULL) || (model.meshMaterial == NULL) || (model.meshCount < 0) || (model.materialCount <= 0)) bad = "model not loaded";
    else if (!rbl__bounded3(position) || !rbl__finite(scale) || !(fabsf(scale) < 1.15e18f)) bad = "NaN/Inf or |value| >= 1.15e18 in position or scale";
    // As DrawModel: transform = model.transform x scale x translation; the albedo colour tinted
    Matrix t = rbl__identity();
    t.m0 = t.m5 = t.m10 = scale;
    t.m12 = position.x; t.m13 = position.y; t.m14 = position.z;
    Matrix transform = rbl__matMul(model.transform, t);
    // A GPU-skinned mesh of a Model with bone matrices is skinned by a skinned program and by the casters
    bool bones = (bad == NULL) && (model.boneMatrices != NULL);
    for (int i = 0; (bad == NULL) && (i < model.meshCount); i++)
    {
        rbl__Program *p = NULL;
        int m = model.meshMaterial[i];
        int path = (bones && rbl__meshGpuSkinned(&model.meshes[i]))? RBL__PATH_SKINNED : RBL__PATH_MESH;
        at = i;
        if ((m < 0) || (m >= model.materialCount)) bad = "a mesh names a material index outside 0..materialCount-1";
        else if ((bad = rbl__meshProblem(&model.meshes[i], &transform)) != NULL) {}
        else if ((path == RBL__PATH_SKINNED) && ((bad = rbl__bonesProblem(&model)) != NULL)) {}
        else bad = rbl__materialProblem(&model.materials[m], path, &p);
    }
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawModel: %s (mesh %i)", bad, at); return; }
    for (int i = 0; i < model.meshCount; i++)
    {
        Material material = model.materials[model.meshMaterial[i]];
        int path = (bones && rbl__meshGpuSkinned(&model.meshes[i]))? RBL__PATH_SKINNED : RBL__PATH_MESH;
        Color c = material.maps[MATERIAL_MAP_ALBEDO].color;
        Color tinted = { (unsigned char)((c.r*tint.r)/255), (unsigned char)((c.g*tint.g)/255), (unsigned char)((c.b*tint.b)/255), (unsigned char)((c.a*tint.a)/255) };
        material.maps[MATERIAL_MAP_ALBEDO].color = tinted;
        rbl__drawMesh(model.meshes[i], material, transform, path, &model);
        material.maps[MATERIAL_MAP_ALBEDO].color = c;
    }
}

// Upload a packed material's Images into the slots the lit shader reads. Mip chains (if packed with
// mipmaps) are uploaded as they are, so the renormalised normal levels are the ones sampled.
bool RblLoadPackedTextures(const RblPackedMaterial *packed, Material *material)
{
    if ((packed == NULL) || (material == NULL) || (material->maps == NULL) || (packed->albedo.data == NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadPackedTextures: missing packed albedo or material maps");
        return false;
    }
    const Image *images[3] = { &packed->albedo, &packed->material, &packed->emissive };
    const int slots[3] = { MATERIAL_MAP_ALBEDO, MATERIAL_MAP_NORMAL, MATERIAL_MAP_EMISSION };
    const RblMaterialLayout *l = &packed->layout;
    const char *bad = NULL;
    if ((l->normalEncoding < RBL_NORMAL_NONE) || (l->normalEncoding > RBL_NORMAL_RGB) || (l->emissive < RBL_EMISSIVE_NONE) || (l->emissive > RBL_EMISSIVE_RGB)) bad = "unknown layout encodings";
    for (int i = 0; (i < 3) && (bad == NULL); i++)
    {
        const Image *im = images[i];
        if (im->data == NULL) continue;
        int levels = 1;
        for (int side = (im->width > im->height)? im->width : im->height; side > 1; side /= 2) levels++;
        if ((im->width != packed->albedo.width) || (im->height != packed->albedo.height) || (im->width <= 0) || (im->height <= 0) || (im->width > RBL__MAX_TEXTURE_SIDE) || (im->height > RBL__MAX_TEXTURE_SIDE)) bad = "an image's size is outside 1..65536 or differs from the albedo's";
        else if ((im->format != PIXELFORMAT_UNCOMPRESSED_GRAYSCALE) && (im->format != PIXELFORMAT_UNCOMPRESSED_R8G8B8A8)) bad = "an image is neither R8 nor RGBA8 (not packed by RblPackMaterial)";
        else if ((im->mipmaps < 1) || (im->mipmaps > levels)) bad = "an image's mipmap count is outside 1..full chain";
    }
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadPackedTextures: %s", bad); return false; }
    Texture2D textures[3];
    memset(textures, 0, sizeof(textures));
    // ES 2 / WebGL1 sample a non-power-of-two texture only without mips and with clamped edges
    // (anything else reads black there): such maps go up as level 0 alone
    const int w = packed->albedo.width, h = packed->albedo.height;
    const bool npotLimited = (rbl__glsl() == 100) && (((w & (w - 1)) != 0) || ((h & (h - 1)) != 0));
    for (int i = 0; i < 3; i++)
    {
        if (images[i]->data == NULL) continue;
        Image upload = *images[i];
        if (npotLimited) upload.mipmaps = 1;
        textures[i] = LoadTextureFromImage(upload);
        if (npotLimited && (textures[i].id != 0)) SetTextureWrap(textures[i], TEXTURE_WRAP_CLAMP);
        if (textures[i].id == 0)
        {
            TraceLog(LOG_WARNING, "RBL: RblLoadPackedTextures: upload failed (no GL context?)");
            for (int k = 0; k < i; k++) if (textures[k].id != 0) UnloadTexture(textures[k]);
            return false;
        }
        SetTextureFilter(textures[i], (textures[i].mipmaps > 1)? TEXTURE_FILTER_TRILINEAR : TEXTURE_FILTER_BILINEAR);
    }
    for (int i = 0; i < 3; i++) if (textures[i].id != 0) material->maps[slots[i]].texture = textures[i];
    return true;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: deferred G-buffer   >>deferred
//----------------------------------------------------------------------------------
// Inverse of a view matrix (rotation + translation): transposed rotation, translation -R^T t
static Matrix rbl__rigidInverse(Matrix view)
{
    float a[16], r[16];
    rbl__matToArray(view, a);
    for (int i = 0; i < 3; i++)
    {
        for (int j = 0; j < 3; j++) r[4*j + i] = a[4*i + j];
        r[12 + i] = -(a[4*i]*a[12] + a[4*i + 1]*a[13] + a[4*i + 2]*a[14]);
        r[4*i + 3] = 0.0f;
    }
    r[15] = 1.0f;
    return rbl__matFromArray(r);
}

// Per-light instance buffer of the volume VAO (created, or re-created when it grows)
static void rbl__loadVolumeInstances(RblGBuffer *g, int capacity)
{
    rlEnableVertexArray(g->state->volumeVao);
    g->state->instanceVbo = rlLoadVertexBuffer(NULL, capacity*RBL__LIGHT_FLOATS*(int)sizeof(float), true);
    for (int a = 0; a < 4; a++)
    {
        rlSetVertexAttribute(RBL__INSTANCE_LOCATION + a, 4, RL_FLOAT, false, RBL__LIGHT_FLOATS*(int)sizeof(float), a*4*(int)sizeof(float));
        rlSetVertexAttributeDivisor(RBL__INSTANCE_LOCATION + a, 1);
        rlEnableVertexAttribute(RBL__INSTANCE_LOCATION + a);
    }
    rlDisableVertexArray();
}

// Sphere proxy enclosing the unit sphere: a UV sphere scaled so every face plane lies outside it
static void rbl__loadVolumeMesh(RblGBuffer *g)
{
    enum { RINGS = 8, SLICES = 12, VERTS = (RINGS + 1)*(SLICES + 1), INDICES = RINGS*SLICES*6 };
    float v[VERTS*3];
    unsigned short idx[INDICES];
    for (int r = 0; r <= RINGS; r++)
        for (int sl = 0; sl <= SLICES; sl++)
        {
            double th = PI*r/(double)RINGS, ph = 2.0*PI*sl/(double)SLICES;     // (double): C++20 deprecates enum-float arithmetic
            float *p = &v[(r*(SLICES + 1) + sl)*3];
            p[0] = (float)(sin(th)*cos(ph)); p[1] = (float)cos(th); p[2] = (float)(sin(th)*sin(ph));
        }
    int n = 0;
    for (int r = 0; r < RINGS; r++)
        for (int sl = 0; sl < SLICES; sl++)
        {
            unsigned short a = (unsigned short)(r*(SLICES + 1) + sl), b = (unsigned short)(a + SLICES + 1);
            // Outward-facing counter-clockwise triangles (degenerate ones at the poles are harmless)
            idx[n++] = a; idx[n++] = (unsigned short)(a + 1); idx[n++] = b;
            idx[n++] = (unsigned short)(a + 1); idx[n++] = (unsigned short)(b + 1); idx[n++] = b;
        }
    // Smallest distance from the centre to a (non-degenerate) face plane: scale so it becomes 1
    double minDist = 1.0;
    for (int i = 0; i < INDICES; i += 3)
    {
        const float *p0 = &v[idx[i]*3], *p1 = &v[idx[i + 1]*3], *p2 = &v[idx[i + 2]*3];
        double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] }, e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
        double c[3] = { e1[1]*e2[2] - e1[2]*e2[1], e1[2]*e2[0] - e1[0]*e2[2], e1[0]*e2[1] - e1[1]*e2[0] };
        double l = sqrt(c[0]*c[0] + c[1]*c[1] + c[2]*c[2]);
        if (l < 1e-9) continue;
        double d = fabs(c[0]*p0[0] + c[1]*p0[1] + c[2]*p0[2])/l;
        if (d < minDist) minDist = d;
    }
    float scale = (float)(1.0/minDist)*1.001f;
    for (int i = 0; i < VERTS*3; i++) v[i] *= scale;

    g->state->volumeVao = rlLoadVertexArray();
    rlEnableVertexArray(g->state->volumeVao);
    g->state->volumeVbo = rlLoadVertexBuffer(v, (int)sizeof(v), false);
    rlSetVertexAttribute(0, 3, RL_FLOAT, false, 0, 0);
    rlEnableVertexAttribute(0);
    g->state->volumeIbo = rlLoadVertexBufferElement(idx, (int)sizeof(idx), false);
    g->state->volumeIndexCount = INDICES;
    rlDisableVertexArray();
    rbl__loadVolumeInstances(g, g->state->instanceCapacity);
    g->state->emptyVao = rlLoadVertexArray();
}

static void rbl__unloadTargets(RblGBuffer *g)
{
    if (!rbl__glUsable())       // gone with the context
    {
        Texture2D *t[6] = { &g->albedo, &g->normal, &g->params, &g->accum, &g->depth, &g->thin };
        for (int i = 0; i < 6; i++) memset(t[i], 0, sizeof(Texture2D));
        g->state->id = 0; g->state->lightId = 0;
        return;
    }
    // rlUnloadFramebuffer deletes the depth texture attached to it (not the colour ones)
    if (g->state->id != 0) { rlUnloadFramebuffer(g->state->id); g->depth.id = 0; }
    if (g->state->lightId != 0) rlUnloadFramebuffer(g->state->lightId);
    Texture2D *t[6] = { &g->albedo, &g->normal, &g->params, &g->accum, &g->depth, &g->thin };
    for (int i = 0; i < 6; i++) { if (t[i]->id != 0) rlUnloadTexture(t[i]->id); memset(t[i], 0, sizeof(Texture2D)); }
    g->state->id = 0; g->state->lightId = 0;
}

static Texture2D rbl__targetTexture(int width, int height, int format)
{
    Texture2D t;
    memset(&t, 0, sizeof(t));
    t.id = rlLoadTexture(NULL, width, height, format, 1);
    t.width = width; t.height = height; t.mipmaps = 1; t.format = format;
    if (t.id != 0)
    {
        rlTextureParameters(t.id, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlTextureParameters(t.id, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlTextureParameters(t.id, RL_TEXTURE_WRAP_S, RL_TEXTURE_WRAP_CLAMP);
        rlTextureParameters(t.id, RL_TEXTURE_WRAP_T, RL_TEXTURE_WRAP_CLAMP);
    }
    return t;
}

// Targets and framebuffers at the G-buffer's size; false (and nothing left loaded) on any failure
// The G-buffer's depth as a 32-bit float texture: rlLoadTextureDepth leaves the format to the driver
// (24-bit, or 32-bit normalised that a sampler may read at 23 bits), and under an orthographic camera
// the window depth is linear over raylib's whole clip range, so each step of it is (far - near)/2^24
// (2.4e-4 world units with raylib's 4000) along the view axis wherever the surface is; the position a
// light pass rebuilds moves a sharp highlight near a light. Float depth keeps what the rasterizer
// computed. The texture's storage is specified again through rlGetProcAddress (rlgl has no call for
// it); without the entry point, or where the format is refused (GL leaves the texture as it was), the
// depth stays as rlgl made it.
static void rbl__floatDepth(unsigned int id, int width, int height)
{
    typedef void (RBL__GLAPI *rbl__TexImage2D)(unsigned int, int, int, int, int, int, unsigned int, unsigned int, const void *);
    void *entry = rlGetProcAddress("glTexImage2D");
    if (entry == NULL) return;
    rbl__TexImage2D texImage2D;
    memcpy(&texImage2D, &entry, sizeof(entry));         // ISO C has no object-to-function pointer cast
    rlEnableTexture(id);
    texImage2D(0x0DE1 /* GL_TEXTURE_2D */, 0, 0x8CAC /* GL_DEPTH_COMPONENT32F */, width, height, 0, 0x1902 /* GL_DEPTH_COMPONENT */, 0x1406 /* GL_FLOAT */, NULL);
    rlDisableTexture();
}

static bool rbl__loadTargets(RblGBuffer *g, int width, int height)
{
    g->albedo = rbl__targetTexture(width, height, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    g->normal = rbl__targetTexture(width, height, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    // RG8 for the 16 parameter bits; ES maps two-channel formats to unrenderable luminance-alpha: RGBA8.
    // A G-buffer receiving shadows keeps each pixel's caster identity there too (RGBA8)
    bool rgba = (rbl__glsl() == 300) || (g->desc.shading.shadowMaps > 0);
    g->params = rbl__targetTexture(width, height, rgba? PIXELFORMAT_UNCOMPRESSED_R8G8B8A8 : PIXELFORMAT_UNCOMPRESSED_GRAY_ALPHA);
    g->accum = rbl__targetTexture(width, height, PIXELFORMAT_UNCOMPRESSED_R16G16B16A16);
    // The thin target: only where the desc asks for transmission or relief (a 5th draw buffer)
    bool thin = g->desc.transmission || g->desc.relief;
    memset(&g->thin, 0, sizeof(g->thin));
    if (thin && (rbl__maxDrawBuffers() >= 5)) g->thin = rbl__targetTexture(width, height, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    memset(&g->depth, 0, sizeof(g->depth));
    g->depth.id = rlLoadTextureDepth(width, height, false);
    if ((g->depth.id != 0) && !RBL__HOOK(gbufferDriverDepth)) rbl__floatDepth(g->depth.id, width, height);
    g->depth.width = width; g->depth.height = height; g->depth.mipmaps = 1;
    bool ok = (g->albedo.id != 0) && (g->normal.id != 0) && (g->params.id != 0) && (g->accum.id != 0) && (g->depth.id != 0) && (!thin || (g->thin.id != 0)) && !RBL__HOOK(gbufferForceFailure);
    if (ok)
    {
        rlTextureParameters(g->depth.id, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlTextureParameters(g->depth.id, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
        g->state->id = rlLoadFramebuffer();
        rlEnableFramebuffer(g->state->id);
        rlFramebufferAttach(g->state->id, g->albedo.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
        rlFramebufferAttach(g->state->id, g->normal.id, RL_ATTACHMENT_COLOR_CHANNEL1, RL_ATTACHMENT_TEXTURE2D, 0);
        rlFramebufferAttach(g->state->id, g->params.id, RL_ATTACHMENT_COLOR_CHANNEL2, RL_ATTACHMENT_TEXTURE2D, 0);
        rlFramebufferAttach(g->state->id, g->accum.id, RL_ATTACHMENT_COLOR_CHANNEL3, RL_ATTACHMENT_TEXTURE2D, 0);
        if (thin) rlFramebufferAttach(g->state->id, g->thin.id, RL_ATTACHMENT_COLOR_CHANNEL4, RL_ATTACHMENT_TEXTURE2D, 0);
        rlFramebufferAttach(g->state->id, g->depth.id, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_TEXTURE2D, 0);
        rlEnableFramebuffer(g->state->id);                 // rlFramebufferAttach() unbinds it again
        rlActiveDrawBuffers(thin? 5 : 4);           // framebuffer state: set once
        ok = rlFramebufferComplete(g->state->id);
        g->state->lightId = rlLoadFramebuffer();
        rlEnableFramebuffer(g->state->lightId);
        rlFramebufferAttach(g->state->lightId, g->accum.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
        ok = ok && rlFramebufferComplete(g->state->lightId);
        rlDisableFramebuffer();
    }
    if (!ok)
    {
        TraceLog(LOG_WARNING, "RBL: G-buffer %ix%i: targets or framebuffer incomplete (%i render targets (GL_MAX_DRAW_BUFFERS %i), an RGBA16F target (ES 3: EXT_color_buffer_float), a depth texture): render forward instead",
                 width, height, thin? 5 : 4, rbl__maxDrawBuffers());
        rbl__unloadTargets(g);
        return false;
    }
    g->width = width; g->height = height;
    return true;
}

// Lighting-pass desc of a G-buffer desc (the registry key of its passes)
static void rbl__gbufferLitDesc(const RblGBufferDesc *g, RblLitShaderDesc *out)
{
    memset(out, 0, sizeof(*out));
    out->maxLights = RBL_MAX_LIGHTS;        // unbounded lights (and the naive loop) go through full-screen passes
    out->shading = g->shading;
    out->transmission = g->transmission; out->shadowTransmittance = g->shadowTransmittance;
}

static void rbl__releasePasses(RblGBuffer *g)
{
    for (int p = 0; p < RBL__PASS_COUNT; p++) if (g->state->passes[p] != 0) rbl__releaseProgram(g->state->passes[p], RBL__KIND_PASS);
    memset(g->state->passes, 0, sizeof(g->state->passes));
}

// A colour + depth texture target; id 0 (problem set) when the context has no such target
static RenderTexture2D rbl__loadSceneTarget(int width, int height)
{
    RenderTexture2D t;
    memset(&t, 0, sizeof(t));
    if ((width <= 0) || (height <= 0) || (width > RBL_MAX_TARGET_SIZE) || (height > RBL_MAX_TARGET_SIZE))
    {
        snprintf(rbl__state.problem, sizeof(rbl__state.problem), "size %ix%i outside 1..RBL_MAX_TARGET_SIZE", width, height);
        return t;
    }
    unsigned int callerTarget = rbl__activeFramebuffer();
    t.id = rlLoadFramebuffer();
    t.texture.id = rlLoadTexture(NULL, width, height, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8, 1);
    t.texture.width = width; t.texture.height = height; t.texture.mipmaps = 1; t.texture.format = PIXELFORMAT_UNCOMPRESSED_R8G8B8A8;
    // A texture, not raylib's renderbuffer, so the depth can be sampled (nearest: one texel per pixel)
    t.depth.id = rlLoadTextureDepth(width, height, false);
    t.depth.width = width; t.depth.height = height; t.depth.mipmaps = 1; t.depth.format = 19;   // as raylib marks depth textures
    bool ok = (t.id != 0) && (t.texture.id != 0) && (t.depth.id != 0), attached = false;
    if (ok)
    {
        attached = true;
        rlTextureParameters(t.depth.id, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlTextureParameters(t.depth.id, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlFramebufferAttach(t.id, t.texture.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
        rlFramebufferAttach(t.id, t.depth.id, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_TEXTURE2D, 0);
        ok = rlFramebufferComplete(t.id);
    }
    rbl__restoreTarget(callerTarget);
    if (!ok)
    {
        snprintf(rbl__state.problem, sizeof(rbl__state.problem), "%ix%i colour + depth texture target unavailable (no depth textures?)", width, height);
        if (t.id != 0) rlUnloadFramebuffer(t.id);       // deletes an attached depth texture
        if (!attached && (t.depth.id != 0)) rlUnloadTexture(t.depth.id);
        if (t.texture.id != 0) rlUnloadTexture(t.texture.id);
        memset(&t, 0, sizeof(t));
    }
    return t;
}

RenderTexture2D RblLoadSceneTarget(int width, int height)
{
    RenderTexture2D t = rbl__loadSceneTarget(width, height);
    if (t.id == 0) TraceLog(LOG_WARNING, "RBL: RblLoadSceneTarget: %s", rbl__state.problem);
    return t;
}

static void rbl__unloadSceneTarget(RenderTexture2D *t)
{
    if (rbl__glUsable() && (t->id != 0))
    {
        rlUnloadFramebuffer(t->id);                     // deletes the attached depth texture
        rlUnloadTexture(t->texture.id);
    }
    memset(t, 0, sizeof(*t));
}

// The header's scene target, its composite program and triangle released (RblClose)
static void rbl__releaseCapture(void)
{
    rbl__SceneCapture *c = &rbl__state.capture;
    rbl__unloadSceneTarget(&c->target);
    if (c->composite != 0) rbl__releaseProgram(c->composite, RBL__KIND_COMPOSITE);
    if (rbl__glUsable() && (c->vao != 0)) rlUnloadVertexArray(c->vao);
    if (rbl__glUsable() && (c->vbo != 0)) rlUnloadVertexBuffer(c->vbo);
    memset(c, 0, sizeof(*c));
}

bool RblBeginSceneDepth(void)
{
    rbl__SceneCapture *c = &rbl__state.capture;
    const char *bad = c->begun? "already in progress (RblEndSceneDepth first)" : (rbl__state.shadowPass != NULL)? "inside a shadow pass" :
                      (rbl__state.gbufferPass != NULL)? "inside a G-buffer's geometry pass" : NULL;
    unsigned int callerTarget = rbl__activeFramebuffer();
    int w = 0, h = 0;
    rbl__targetSize(callerTarget, &w, &h);
    if ((bad == NULL) && (c->composite == 0))
    {
        // First use: the composite program and a full-screen triangle (kept until RblClose)
        rbl__ProgramKey key;
        memset(&key, 0, sizeof(key));
        key.kind = RBL__KIND_COMPOSITE;
        rbl__Program *p = rbl__acquireProgram(&key);
        if (p == NULL) bad = rbl__state.problem;
        else
        {
            c->composite = p->shader.id;
            const float triangle[9] = { -1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f };
            c->vao = rlLoadVertexArray();          // 0 where the context has none: attributes set per draw
            if (c->vao != 0) rlEnableVertexArray(c->vao);
            c->vbo = rlLoadVertexBuffer(triangle, (int)sizeof(triangle), false);
            if (c->vao != 0)
            {
                rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION, 3, RL_FLOAT, false, 0, 0);
                rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION);
                rlDisableVertexArray();
            }
            if (c->vbo == 0) bad = "the full-screen triangle's buffer could not be created";
        }
    }
    // The target follows the size of the one it is shown on (a resized window never stretches it)
    if ((bad == NULL) && ((c->target.id == 0) || (c->target.texture.width != w) || (c->target.texture.height != h)))
    {
        RenderTexture2D t = rbl__loadSceneTarget(w, h);
        if (t.id == 0) bad = rbl__state.problem;
        else { rbl__unloadSceneTarget(&c->target); c->target = t; }
    }
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblBeginSceneDepth: %s", bad); return false; }
    rlDrawRenderBatchActive();
    c->savedFramebuffer = callerTarget;
    rlEnableFramebuffer(c->target.id);
    rlViewport(0, 0, w, h);
    rlClearColor(0, 0, 0, 0);
    rlClearScreenBuffers();
    c->begun = true;
    return true;
}

void RblEndSceneDepth(void)
{
    rbl__SceneCapture *c = &rbl__state.capture;
    if (!c->begun) { TraceLog(LOG_WARNING, "RBL: RblEndSceneDepth: no RblBeginSceneDepth in progress"); return; }
    rlDrawRenderBatchActive();
    rbl__restoreTarget(c->savedFramebuffer);
    const rbl__Program *p = rbl__findOwn(c->composite, RBL__KIND_COMPOSITE);
    rlEnableShader(p->shader.id);
    int units[2] = { 0, 1 };
    rlSetUniform(rlGetLocationUniform(p->shader.id, "texture0"), &units[0], SHADER_UNIFORM_INT, 1);
    rlSetUniform(rlGetLocationUniform(p->shader.id, "rblSceneDepthMap"), &units[1], SHADER_UNIFORM_INT, 1);
    rlActiveTextureSlot(0); rlEnableTexture(c->target.texture.id);
    rlActiveTextureSlot(1); rlEnableTexture(c->target.depth.id);
    rlDisableColorBlend();                          // the world is opaque: its colour and depth replace the target's
    rlEnableDepthTest();
    rlEnableDepthMask();
    rlDisableBackfaceCulling();
    if ((c->vao == 0) || !rlEnableVertexArray(c->vao))
    {
        rlEnableVertexBuffer(c->vbo);
        rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION, 3, RL_FLOAT, false, 0, 0);
        rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION);
    }
    rlDrawVertexArray(0, 3);
    rlDisableVertexArray();
    rlDisableVertexBuffer();
    rlEnableBackfaceCulling();
    rlDisableDepthTest();                           // raylib's 2D state (BeginMode3D turns it on again)
    rlEnableColorBlend();
    rlActiveTextureSlot(1); rlDisableTexture();
    rlActiveTextureSlot(0); rlDisableTexture();
    rlDisableShader();
    c->begun = false;
    c->shown = true;
}

RblGBuffer RblLoadGBuffer(RblGBufferDesc desc)
{
    RblGBuffer g;
    memset(&g, 0, sizeof(g));
    int width = desc.width, height = desc.height;
    const bool follow = (width == 0) && (height == 0);
    if (follow) rbl__targetSize(rbl__activeFramebuffer(), &width, &height);
    RblLitShaderDesc lit, normalised;
    rbl__gbufferLitDesc(&desc, &lit);
    const char *bad = rbl__normaliseLitDesc(lit, &normalised);
    if ((bad == NULL) && ((width <= 0) || (height <= 0) || (width > RBL_MAX_TARGET_SIZE) || (height > RBL_MAX_TARGET_SIZE))) bad = "size outside 1..RBL_MAX_TARGET_SIZE";
    if (bad == NULL) bad = rbl__needsGlsl3("the G-buffer and deferred passes");
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadGBuffer: %s", bad); return g; }
    g.state = (rbl__GBufferState *)RBL_CALLOC(1, sizeof(rbl__GBufferState));
    if ((g.state == NULL) || ((g.id = rbl__liveAdd(g.state)) == 0))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadGBuffer: out of memory");
        RBL_FREE(g.state);
        memset(&g, 0, sizeof(g));
        return g;
    }
    unsigned int callerTarget = rbl__activeFramebuffer();
    g.desc = desc;                  // rbl__loadTargets reads shadowMaps
    if (!rbl__loadTargets(&g, width, height)) { rbl__restoreTarget(callerTarget); RblUnloadGBuffer(&g); return g; }
    rbl__restoreTarget(callerTarget);
    g.desc = desc;
    g.desc.width = width; g.desc.height = height;
    g.desc.shading.lightFeatures = normalised.shading.lightFeatures; g.desc.shading.shadowFilter = normalised.shading.shadowFilter;

    // Pass programs from the registry: the forward path's lights.glsl and output.glsl in the deferred stages
    bool ok = true;
    for (int p = 0; (p < RBL__PASS_COUNT) && ok; p++)
    {
        rbl__ProgramKey key;
        rbl__keyFromDesc(&normalised, RBL__KIND_PASS, p, &key);
        if (p == RBL__PASS_RESOLVE) { key.desc.transmission = false; key.desc.shadowTransmittance = false; }    // the resolve reads neither
        else key.gbufferRelief = desc.relief? 1 : 0;
        rbl__Program *program = rbl__acquireProgram(&key);
        ok = (program != NULL);
        if (ok) g.state->passes[p] = program->shader.id;
    }
    if (!ok)
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadGBuffer: a lighting pass could not be loaded (%s): render forward instead", rbl__state.problem);
        RblUnloadGBuffer(&g);
        return g;
    }
    g.state->instanceCapacity = 256;
    g.state->follow = follow;
    rbl__loadVolumeMesh(&g);
    g.outputScale = 1.0f;
    g.state->view = rbl__identity(); g.state->projection = rbl__identity();
    TraceLog(LOG_INFO, "RBL: G-buffer %ix%i loaded (%i bytes/pixel + depth + RGBA16F accumulation)", width, height, RblGBufferBytesPerPixel(&g));
    return g;
}

// Membership first: a stale copy's state (its G-buffer unloaded) is never read
static bool rbl__gbufferValid(const RblGBuffer *gbuffer)
{
    return (gbuffer != NULL) && rbl__isLive(gbuffer->id, gbuffer->state) && (gbuffer->state->id != 0) && (gbuffer->state->lightId != 0) && (gbuffer->state->passes[RBL__PASS_RESOLVE] != 0) && (gbuffer->state->volumeVao != 0);
}

bool RblIsGBufferValid(RblGBuffer gbuffer) { return rbl__gbufferValid(&gbuffer); }

// New targets at width x height (passes kept); false (logged by rbl__loadTargets) keeps the old ones
static bool rbl__resizeTargets(RblGBuffer *gbuffer, int width, int height)
{
    if ((width == gbuffer->width) && (height == gbuffer->height)) return true;
    rbl__GBufferState freshState = *gbuffer->state;
    RblGBuffer fresh = *gbuffer;
    fresh.state = &freshState;
    unsigned int callerTarget = rbl__activeFramebuffer();
    bool ok = rbl__loadTargets(&fresh, width, height);
    rbl__restoreTarget(callerTarget);
    if (!ok) return false;
    rbl__unloadTargets(gbuffer);
    gbuffer->state->id = fresh.state->id; gbuffer->state->lightId = fresh.state->lightId;
    gbuffer->albedo = fresh.albedo; gbuffer->normal = fresh.normal; gbuffer->params = fresh.params;
    gbuffer->accum = fresh.accum; gbuffer->depth = fresh.depth; gbuffer->thin = fresh.thin;
    gbuffer->width = width; gbuffer->height = height;
    gbuffer->desc.width = width; gbuffer->desc.height = height;
    gbuffer->state->geometryDone = false;       // new targets hold nothing yet
    return true;
}

bool RblResizeGBuffer(RblGBuffer *gbuffer, int width, int height)
{
    if (!rbl__gbufferValid(gbuffer) || (width <= 0) || (height <= 0) || (width > RBL_MAX_TARGET_SIZE) || (height > RBL_MAX_TARGET_SIZE) || gbuffer->state->begun)
    {
        TraceLog(LOG_WARNING, "RBL: RblResizeGBuffer: invalid G-buffer (or inside its pass) or size %ix%i outside 1..%i", width, height, RBL_MAX_TARGET_SIZE);
        return false;
    }
    if (!rbl__resizeTargets(gbuffer, width, height)) return false;
    gbuffer->state->follow = false;         // sized by the caller from now on
    return true;
}

void RblUnloadGBuffer(RblGBuffer *gbuffer)
{
    if (!rbl__unloadable(gbuffer, (gbuffer != NULL)? gbuffer->id : 0, (gbuffer != NULL)? gbuffer->state : NULL, "RblUnloadGBuffer", "G-buffer")) { if (gbuffer != NULL) memset(gbuffer, 0, sizeof(*gbuffer)); return; }
    if (gbuffer->state->begun) { TraceLog(LOG_WARNING, "RBL: RblUnloadGBuffer: its geometry pass is in progress (RblEndGBuffer first)"); return; }
    rbl__unloadTargets(gbuffer);
    rbl__releasePasses(gbuffer);
    if (!rbl__glUsable()) gbuffer->state->volumeVao = gbuffer->state->emptyVao = gbuffer->state->volumeVbo = gbuffer->state->volumeIbo = gbuffer->state->instanceVbo = 0;
    if (gbuffer->state->volumeVao != 0) rlUnloadVertexArray(gbuffer->state->volumeVao);
    if (gbuffer->state->emptyVao != 0) rlUnloadVertexArray(gbuffer->state->emptyVao);
    if (gbuffer->state->volumeVbo != 0) rlUnloadVertexBuffer(gbuffer->state->volumeVbo);
    if (gbuffer->state->volumeIbo != 0) rlUnloadVertexBuffer(gbuffer->state->volumeIbo);
    if (gbuffer->state->instanceVbo != 0) rlUnloadVertexBuffer(gbuffer->state->instanceVbo);
    rbl__liveRemove(gbuffer->id);
    RBL_FREE(gbuffer->state);
    memset(gbuffer, 0, sizeof(*gbuffer));
    rbl__tidyAfterClose();
}

int RblGBufferBytesPerPixel(const RblGBuffer *gbuffer)
{
    if (!rbl__gbufferValid(gbuffer)) { TraceLog(LOG_WARNING, "RBL: RblGBufferBytesPerPixel: G-buffer not loaded"); return 0; }
    return GetPixelDataSize(1, 1, gbuffer->albedo.format) + GetPixelDataSize(1, 1, gbuffer->normal.format) + GetPixelDataSize(1, 1, gbuffer->params.format) +
           ((gbuffer->thin.id != 0)? GetPixelDataSize(1, 1, gbuffer->thin.format) : 0);
}

// View matrix in raylib's layout (as MatrixLookAt), from the header's degenerate-safe camera frame
static Matrix rbl__viewMatrix(const RblCameraFrame *v)
{
    Matrix m;
    m.m0 = v->right.x; m.m1 = v->up.x; m.m2 = v->back.x; m.m3 = 0.0f;
    m.m4 = v->right.y; m.m5 = v->up.y; m.m6 = v->back.y; m.m7 = 0.0f;
    m.m8 = v->right.z; m.m9 = v->up.z; m.m10 = v->back.z; m.m11 = 0.0f;
    m.m12 = -rbl__dot(v->right, v->eye); m.m13 = -rbl__dot(v->up, v->eye); m.m14 = -rbl__dot(v->back, v->eye); m.m15 = 1.0f;
    return m;
}

// The scene's ambient as the resolve adds it: sky, ground, up
static void rbl__sceneAmbient(float out[9])
{
    const rbl__Scene *s = &rbl__state.scene;
    memcpy(&out[0], s->ambient, sizeof(s->ambient));
    memcpy(&out[3], s->ground, sizeof(s->ground));
    memcpy(&out[6], s->up, sizeof(s->up));
}

bool RblBeginGBuffer(RblGBuffer *gbuffer, Camera3D camera)
{
    const char *bad = NULL;
    if (!rbl__gbufferValid(gbuffer)) bad = "invalid G-buffer";
    else if (gbuffer->state->begun || (rbl__state.gbufferPass != NULL)) bad = "a G-buffer pass is already in progress (RblEndGBuffer first)";
    else if (rbl__state.shadowPass != NULL) bad = "inside a shadow pass";
    else if (!rbl__cameraOk(camera)) bad = "camera with NaN/Inf or huge fields, fovy outside (0, 180) or unknown projection";
    unsigned int callerTarget = rbl__activeFramebuffer();
    int w = 0, h = 0;
    if ((bad == NULL) && gbuffer->state->follow)
    {
        // Loaded with size 0: the size of what it renders for (the screen, or the render texture of
        // BeginTextureMode), taken here so a resized window never stretches it
        rbl__targetSize(callerTarget, &w, &h);
        if ((w <= 0) || (h <= 0) || (w > RBL_MAX_TARGET_SIZE) || (h > RBL_MAX_TARGET_SIZE)) bad = "the target's size is outside 1..RBL_MAX_TARGET_SIZE";
        else if (((w != gbuffer->width) || (h != gbuffer->height)) && !rbl__resizeTargets(gbuffer, w, h)) bad = "the G-buffer could not take its target's new size (the old targets are kept)";
    }
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblBeginGBuffer: %s", bad); return false; }
    gbuffer->state->savedFramebuffer = callerTarget;
    rlDrawRenderBatchActive();
    rlEnableFramebuffer(gbuffer->state->id);
    rlViewport(0, 0, gbuffer->width, gbuffer->height);
    rlDisableColorBlend();                          // G-buffer values are data: never blended
    rlEnableDepthTest();
    rlEnableDepthMask();
    rlClearColor(0, 0, 0, 0);
    rlClearScreenBuffers();
    // The projection BeginMode3D() would build for a target of this size
    rlMatrixMode(RL_PROJECTION);
    rlPushMatrix();
    rlLoadIdentity();
    double aspect = (double)gbuffer->width/(double)gbuffer->height;
    double nearPlane = rlGetCullDistanceNear(), farPlane = rlGetCullDistanceFar();
    if (camera.projection == CAMERA_ORTHOGRAPHIC)
    {
        double top = camera.fovy/2.0, right = top*aspect;
        rlOrtho(-right, right, -top, top, nearPlane, farPlane);
    }
    else
    {
        double top = nearPlane*tan(camera.fovy*0.5*DEG2RAD), right = top*aspect;
        rlFrustum(-right, right, -top, top, nearPlane, farPlane);
    }
    rlMatrixMode(RL_MODELVIEW);
    rlLoadIdentity();
    RblCameraFrame v = rbl__cameraFrame(camera);
    float view[16];
    rbl__matToArray(rbl__viewMatrix(&v), view);
    rlMultMatrixf(view);
    gbuffer->state->view = rlGetMatrixModelview();
    gbuffer->state->projection = rlGetMatrixProjection();
    gbuffer->state->eye = camera.position;
    rbl__sceneAmbient(gbuffer->state->ambient);
    gbuffer->state->begun = true;
    rbl__state.gbufferPassBuffer = *gbuffer;
    rbl__state.gbufferPass = &rbl__state.gbufferPassBuffer;
    return true;
}

void RblEndGBuffer(RblGBuffer *gbuffer)
{
    if ((gbuffer == NULL) || !rbl__isLive(gbuffer->id, gbuffer->state) || !gbuffer->state->begun) { TraceLog(LOG_WARNING, "RBL: RblEndGBuffer: no G-buffer pass of this G-buffer in progress"); return; }
    gbuffer->state->begun = false;
    gbuffer->state->geometryDone = true;
    rbl__state.gbufferPass = NULL;
    rlDrawRenderBatchActive();
    rlMatrixMode(RL_PROJECTION);
    rlPopMatrix();
    rlMatrixMode(RL_MODELVIEW);
    rlLoadIdentity();
    rlEnableColorBlend();
    rlDisableDepthTest();
    rbl__restoreTarget(gbuffer->state->savedFramebuffer);     // the caller's target (e.g. inside BeginTextureMode)
}

// Registry entry of one of the G-buffer's pass programs
// (a receiving pass: its variant for the scene's map kinds)
static rbl__Program *rbl__passProgram(const RblGBuffer *g, int pass) { return rbl__shadowVariant(rbl__findOwn(g->state->passes[pass], RBL__KIND_PASS)); }

// Binds the G-buffer textures, camera and shadow uniforms of one pass; returns its locations
static const int *rbl__bindGBufferPass(const RblGBuffer *g, int pass)
{
    const rbl__Program *program = rbl__passProgram(g, pass);
    const int *loc = program->loc;
    rlEnableShader(program->shader.id);
    unsigned int tex[5] = { g->albedo.id, g->normal.id, g->params.id, g->depth.id, g->accum.id };
    for (int i = 0; i < 5; i++)
    {
        if (loc[RBL__U_G_ALBEDO + i] == -1) continue;
        rlActiveTextureSlot(i);
        rlEnableTexture(tex[i]);
        rlSetUniform(loc[RBL__U_G_ALBEDO + i], &i, SHADER_UNIFORM_INT, 1);
    }
    if (loc[RBL__U_INV_VIEW] != -1) rlSetUniformMatrix(loc[RBL__U_INV_VIEW], rbl__rigidInverse(g->state->view));
    if (loc[RBL__U_MVP] != -1) rlSetUniformMatrix(loc[RBL__U_MVP], rbl__matMul(g->state->view, g->state->projection));
    float eye[3] = { g->state->eye.x, g->state->eye.y, g->state->eye.z };
    if (loc[RBL__U_EYE] != -1) rlSetUniform(loc[RBL__U_EYE], eye, SHADER_UNIFORM_VEC3, 1);
    // View position from window depth, in closed form (gbuffer_read.glsl): perspective (w = 1) or orthographic
    double n = rlGetCullDistanceNear(), f = rlGetCullDistanceFar();
    bool perspective = (g->state->projection.m15 == 0.0f);
    // View vector (common.glsl rblViewVector): the view matrix's row 2 is the back direction
    float viewAxis[4] = { g->state->view.m2, g->state->view.m6, g->state->view.m10, perspective? 0.0f : 1.0f };
    if (loc[RBL__U_VIEW_AXIS] != -1) rlSetUniform(loc[RBL__U_VIEW_AXIS], viewAxis, SHADER_UNIFORM_VEC4, 1);
    float depthLinear[4] = { perspective? (float)(n*f) : (float)n, (float)(f - n), (float)f, perspective? 1.0f : 0.0f };
    float invP[2] = { 1.0f/g->state->projection.m0, 1.0f/g->state->projection.m5 };
    if (loc[RBL__U_DEPTH_LINEAR] != -1) rlSetUniform(loc[RBL__U_DEPTH_LINEAR], depthLinear, SHADER_UNIFORM_VEC4, 1);
    if (loc[RBL__U_INV_P] != -1) rlSetUniform(loc[RBL__U_INV_P], invP, SHADER_UNIFORM_VEC2, 1);
    if ((loc[RBL__U_G_THIN] != -1) && (g->thin.id != 0))
    {
        int unit = 5;
        rlActiveTextureSlot(unit);
        rlEnableTexture(g->thin.id);
        rlSetUniform(loc[RBL__U_G_THIN], &unit, SHADER_UNIFORM_INT, 1);
    }
    rbl__bindSceneShadows();
    if (program->key.desc.shadowTransmittance) rbl__bindSceneTints(program);
    return loc;
}

static void rbl__unbindGBufferPass(void)
{
    for (int i = 5; i >= 0; i--) { rlActiveTextureSlot(i); rlDisableTexture(); }
    rlDisableShader();
}

// Full-screen pass over unbounded lights (the forward shader's uniform arrays; the ambient was added
// by the geometry pass)
static void rbl__fullscreenLights(RblGBuffer *g, int pass, const float *pos, const float *col, const float *spot, const float *att, int count, const int shadowSlot[4], const int *reliefIndex)
{
    const int *loc = rbl__bindGBufferPass(g, pass);
    if ((loc[RBL__U_RELIEF_INDEX] != -1) && (count > 0)) rlSetUniform(loc[RBL__U_RELIEF_INDEX], reliefIndex, SHADER_UNIFORM_INT, count);
    const rbl__Scene *s = &rbl__state.scene;
    if (loc[RBL__U_SHADOW_PARAMS] != -1)
    {
        // The registry's shadow upload, with this chunk's slots
        int n = (s->shadowCount < g->desc.shading.shadowMaps)? s->shadowCount : g->desc.shading.shadowMaps;
        int slots[RBL_MAX_SHADOWS] = { -1, -1, -1, -1 };
        for (int k = 0; k < n; k++) slots[k] = shadowSlot[k];
        rbl__uploadShadows(rbl__passProgram(g, pass), slots);
    }
    if (loc[RBL__U_LIGHT_COUNT] != -1) rlSetUniform(loc[RBL__U_LIGHT_COUNT], &count, SHADER_UNIFORM_INT, 1);
    if (count > 0)
    {
        if (loc[RBL__U_LIGHT_POSITION] != -1) rlSetUniform(loc[RBL__U_LIGHT_POSITION], pos, SHADER_UNIFORM_VEC4, count);
        if (loc[RBL__U_LIGHT_COLOR] != -1) rlSetUniform(loc[RBL__U_LIGHT_COLOR], col, SHADER_UNIFORM_VEC4, count);
        if (loc[RBL__U_LIGHT_SPOT] != -1) rlSetUniform(loc[RBL__U_LIGHT_SPOT], spot, SHADER_UNIFORM_VEC4, count);
        if (loc[RBL__U_LIGHT_ATTENUATION] != -1) rlSetUniform(loc[RBL__U_LIGHT_ATTENUATION], att, SHADER_UNIFORM_VEC3, count);
    }
    rlDisableBackfaceCulling();
    rlEnableVertexArray(g->state->emptyVao);
    rlDrawVertexArray(0, 3);
    rlDisableVertexArray();
    rbl__unbindGBufferPass();
}

// A packed light goes through a full-screen pass when it has no range (directional, range 0) or the
// naive loop is asked for
#if defined(RBL_INSTRUMENTS)
    #define RBL__NAIVE(g) ((g)->naiveFullscreen)
#else
    #define RBL__NAIVE(g) ((void)(g), false)
#endif
static bool rbl__fullscreenLight(const RblGBuffer *g, const float *slot) { return !(slot[7] > 0.0f) || RBL__NAIVE(g); }

bool RblDrawDeferredLights(RblGBuffer *gbuffer)
{
    const char *bad = NULL;
    if (!rbl__gbufferValid(gbuffer)) bad = "invalid G-buffer";
    else if (gbuffer->state->begun) bad = "inside the geometry pass (RblEndGBuffer first)";
    else if (rbl__state.shadowPass != NULL) bad = "inside a shadow pass";
    else if (rbl__state.gbufferPass != NULL) bad = "inside another G-buffer's geometry pass";
    else if (!gbuffer->state->geometryDone) bad = "no geometry pass ran since the G-buffer was loaded or resized (RblBeginGBuffer/RblEndGBuffer first)";
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawDeferredLights: %s", bad); return false; }
    if (rbl__state.scene.shadowDropped && (gbuffer->desc.shading.shadowMaps > 0)) rbl__noteDroppedShadow();
    RblGBuffer *g = gbuffer;
    const rbl__Scene *s = &rbl__state.scene;
    int count = s->lightCount, unbounded = 0, uncompiled = 0;
    for (int i = 0; i < count; i++)
    {
        if ((s->lightFeatures[i] & ~g->desc.shading.lightFeatures & ~RBL_LIGHT_FEATURE_POINT) != 0) uncompiled++;
        else if (rbl__fullscreenLight(g, &s->lights[i*RBL__LIGHT_FLOATS])) unbounded++;
    }
    if (!RBL__NAIVE(g) && (unbounded > RBL_MAX_LIGHTS))
    {
        TraceLog(LOG_WARNING, "RBL: RblDrawDeferredLights: %i unbounded lights (directional or range 0), at most RBL_MAX_LIGHTS (%i)", unbounded, RBL_MAX_LIGHTS);
        return false;
    }
    if (uncompiled > 0) TraceLog(LOG_INFO, "RBL: RblDrawDeferredLights: %i light(s) of types not in the G-buffer's lightFeatures left out", uncompiled);
    // The frame's ambient is the geometry pass's scene's: a scene set since then with another one is noted once
    float now[9];
    rbl__sceneAmbient(now);
    if (!g->state->ambientNoted && (memcmp(now, g->state->ambient, sizeof(now)) != 0))
    {
        TraceLog(LOG_INFO, "RBL: RblDrawDeferredLights: the scene's ambient changed after the geometry pass, whose scene's ambient the frame keeps (RblSetScene before RblBeginGBuffer)");
        g->state->ambientNoted = true;
    }
    // Volumes need the instance buffer to hold every bounded light (grown with a log line)
    if (count > g->state->instanceCapacity)
    {
        int capacity = g->state->instanceCapacity;
        while (capacity < count) capacity *= 2;
        rlUnloadVertexBuffer(g->state->instanceVbo);
        rbl__loadVolumeInstances(g, capacity);
        TraceLog(LOG_INFO, "RBL: G-buffer light volumes grown from %i to %i", g->state->instanceCapacity, capacity);
        g->state->instanceCapacity = capacity;
    }
    float pos[RBL_MAX_LIGHTS*4], col[RBL_MAX_LIGHTS*4], spot[RBL_MAX_LIGHTS*4], att[RBL_MAX_LIGHTS*3];
    int reliefIndex[RBL_MAX_LIGHTS];        // scene index of each slot's relief bit (-1: lights 8 and later have none)
    bool counting = (g->output == RBL_GBUFFER_OUTPUT_LIGHT_COUNT);

    rlDrawRenderBatchActive();
    unsigned int callerTarget = rbl__activeFramebuffer();
    rlEnableFramebuffer(g->state->lightId);
    rlViewport(0, 0, g->width, g->height);
    rlDisableDepthTest();
    rlSetBlendFactors(RL_ONE, RL_ONE, RL_FUNC_ADD);     // light adds up in the accumulation target
    rlSetBlendMode(BLEND_CUSTOM);
    rlEnableColorBlend();
    if (counting) { rlClearColor(0, 0, 0, 0); rlClearScreenBuffers(); }   // the count replaces the emission

    // Full-screen: every unbounded light, in chunks of RBL_MAX_LIGHTS (none: no pass)
    int passFullscreen = counting? RBL__PASS_FULLSCREEN_COUNT : RBL__PASS_FULLSCREEN;
    int n = 0;
    int shadowSlot[4] = { -1, -1, -1, -1 };                 // slot of each shadowed light in this chunk
    for (int i = 0; i <= count; i++)
    {
        const float *d = (i < count)? &s->lights[i*RBL__LIGHT_FLOATS] : NULL;
        if ((d != NULL) && ((s->lightFeatures[i] & ~g->desc.shading.lightFeatures & ~RBL_LIGHT_FEATURE_POINT) == 0) && rbl__fullscreenLight(g, d))
        {
            memcpy(&pos[n*4], &d[0], 4*sizeof(float)); memcpy(&col[n*4], &d[4], 4*sizeof(float));
            memcpy(&spot[n*4], &d[8], 4*sizeof(float)); memcpy(&att[n*3], &d[12], 3*sizeof(float));
            if (d[15] > 0.0f) shadowSlot[(int)d[15] - 1] = n;
            reliefIndex[n] = (i < 8)? i : -1;
            n++;
        }
        if ((n == RBL_MAX_LIGHTS) || ((i == count) && (n > 0)))
        {
            rbl__fullscreenLights(g, passFullscreen, pos, col, spot, att, n, shadowSlot, reliefIndex);
            for (int k = 0; k < 4; k++) shadowSlot[k] = -1;
            n = 0;
        }
    }
    g->lightsFullscreen = unbounded;
    // Volumes: bounded lights gathered in order, then one instanced draw of sphere proxies, back
    // faces only (correct with the eye inside one)
    int v = 0;
    for (int i = 0; (i < count) && !RBL__NAIVE(g); i++)
    {
        const float *d = &s->lights[i*RBL__LIGHT_FLOATS];
        if (((s->lightFeatures[i] & ~g->desc.shading.lightFeatures & ~RBL_LIGHT_FEATURE_POINT) != 0) || rbl__fullscreenLight(g, d)) continue;
        memcpy(&s->staging[v*RBL__LIGHT_FLOATS], d, RBL__LIGHT_FLOATS*sizeof(float));
        if (g->desc.relief && (i < 8)) s->staging[v*RBL__LIGHT_FLOATS + 15] += 8.0f*(float)(i + 1);   // + its relief bit (deferred_volume.fs.glsl)
        v++;
    }
    g->lightsInVolumes = v;
    if (v > 0)
    {
        int pass = counting? RBL__PASS_VOLUME_COUNT : RBL__PASS_VOLUME;
        rbl__bindGBufferPass(g, pass);
        const rbl__Program *volume = rbl__passProgram(g, pass);
        if (volume->loc[RBL__U_SHADOW_PARAMS] != -1)
        {
            int none[RBL_MAX_SHADOWS] = { -1, -1, -1, -1 };
            rbl__uploadShadows(volume, none);       // each volume carries its own map index
        }
        rlEnableBackfaceCulling();
        rlSetCullFace(RL_CULL_FACE_FRONT);
        rlEnableVertexArray(g->state->volumeVao);
        rlUpdateVertexBuffer(g->state->instanceVbo, s->staging, v*RBL__LIGHT_FLOATS*(int)sizeof(float), 0);
        rlDrawVertexArrayElementsInstanced(0, g->state->volumeIndexCount, 0, v);
        rlDisableVertexArray();
        rlSetCullFace(RL_CULL_FACE_BACK);
        rbl__unbindGBufferPass();
    }
    rlEnableBackfaceCulling();
    rlSetBlendMode(BLEND_ALPHA);
    rbl__restoreTarget(callerTarget);
    return true;
}

void RblSetGBufferOutput(RblGBuffer *gbuffer, int view, float scale)
{
    if (!rbl__gbufferValid(gbuffer) || (view < 0) || (view >= RBL_GBUFFER_OUTPUT_COUNT) || !rbl__finite(scale) || (scale < 0.0f))
    {
        TraceLog(LOG_WARNING, "RBL: RblSetGBufferOutput: G-buffer not loaded, unknown view %i or bad scale", view);
        return;
    }
    gbuffer->output = view;
    gbuffer->outputScale = (scale > 0.0f)? scale : 1.0f;
}

void RblResolveGBuffer(RblGBuffer *gbuffer)
{
    const char *bad = !rbl__gbufferValid(gbuffer)? "invalid G-buffer" : gbuffer->state->begun? "inside its geometry pass" :
                      (rbl__state.shadowPass != NULL)? "inside a shadow pass" : (rbl__state.gbufferPass != NULL)? "inside another G-buffer's geometry pass" : NULL;
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblResolveGBuffer: %s", bad); return; }
    RblGBuffer *g = gbuffer;
    int w, h;
    rbl__targetSize(rbl__activeFramebuffer(), &w, &h);
    if (((w != g->width) || (h != g->height)) && !g->state->sizeNoted)
        TraceLog(LOG_WARNING, "RBL: RblResolveGBuffer: the G-buffer is %ix%i and its target %ix%i: the image is scaled (load it with size 0 to follow its target)", g->width, g->height, w, h);
    g->state->sizeNoted = (w != g->width) || (h != g->height);
    rlDrawRenderBatchActive();
    const int *loc = rbl__bindGBufferPass(g, RBL__PASS_RESOLVE);
    if (loc[RBL__U_OUTPUT] != -1) rlSetUniform(loc[RBL__U_OUTPUT], &g->output, SHADER_UNIFORM_INT, 1);
    if (loc[RBL__U_OUTPUT_SCALE] != -1) rlSetUniform(loc[RBL__U_OUTPUT_SCALE], &g->outputScale, SHADER_UNIFORM_FLOAT, 1);
    // The ambient of the scene the geometry pass was drawn with (RblBeginGBuffer's), once per pixel here
    if (loc[RBL__U_AMBIENT] != -1) rlSetUniform(loc[RBL__U_AMBIENT], &g->state->ambient[0], SHADER_UNIFORM_VEC3, 1);
    if (loc[RBL__U_AMBIENT_GROUND] != -1) rlSetUniform(loc[RBL__U_AMBIENT_GROUND], &g->state->ambient[3], SHADER_UNIFORM_VEC3, 1);
    if (loc[RBL__U_AMBIENT_UP] != -1) rlSetUniform(loc[RBL__U_AMBIENT_UP], &g->state->ambient[6], SHADER_UNIFORM_VEC3, 1);
    rlEnableDepthTest();                            // the G-buffer depth is written for later forward draws
    rlEnableDepthMask();
    rlDisableBackfaceCulling();
    rlEnableVertexArray(g->state->emptyVao);
    rlDrawVertexArray(0, 3);
    rlDisableVertexArray();
    rlEnableBackfaceCulling();
    rlDisableDepthTest();
    rbl__unbindGBufferPass();
}

//----------------------------------------------------------------------------------
// Module Functions Definition: shadows   >>shadows
//----------------------------------------------------------------------------------
// The billboard frame of a shadow pass: the light's own frame (the default: casters face the light),
// or the caller's camera (desc.faceCamera: the shadow matches what is seen); AXIS billboards get the
// light and minimum angle to tilt by (rbl__castOf)
static void rbl__shadowPassView(RblCameraFrame *view)
{
    if (!rbl__state.shadowPass->desc.faceCamera) *view = rbl__state.shadowPass->state->lightView;
}

// The light AXIS billboards tilt toward in map's pass
static rbl__Cast rbl__castOf(const RblShadowMap *map)
{
    rbl__Cast cast;
    Vector3 toLight = rbl__neg(rbl__cross(map->state->lightView.up, map->state->lightView.right));    // = back
    if (map->state->lightType != RBL_LIGHT_DIRECTIONAL) { cast.light.x = map->state->lightView.eye.x; cast.light.y = map->state->lightView.eye.y; cast.light.z = map->state->lightView.eye.z; cast.light.w = 1.0f; }
    else { cast.light.x = toLight.x; cast.light.y = toLight.y; cast.light.z = toLight.z; cast.light.w = 0.0f; }
    cast.minSin = (map->desc.minCastAngle > 0.0f)? sinf(map->desc.minCastAngle*(PI/180.0f)) : 0.0f;
    cast.faceLight = !map->desc.faceCamera;
    cast.radial = cast.faceLight && (map->state->kind == RBL__SHADOW_OMNI);
    return cast;
}

// Defaults applied; NULL or the reason it is rejected
static const char *rbl__normaliseShadowDesc(RblShadowDesc in, RblShadowDesc *out)
{
    memset(out, 0, sizeof(*out));
    if ((in.size != 0) && ((in.size < 16) || (in.size > RBL_MAX_TARGET_SIZE))) return "size outside 16..RBL_MAX_TARGET_SIZE";
    if (!rbl__finite(in.constantBias) || !rbl__finite(in.slopeBias) || !rbl__finite(in.normalBias) || !rbl__finite(in.minCastAngle)) return "NaN/Inf bias or angle";
    if (in.minCastAngle > 80.0f) return "minCastAngle above 80 degrees";
    if (!rbl__finite(in.cascadeLambda) || !rbl__finite(in.cascadeBlend) || (in.cascadeLambda > 1.0f) || (in.cascadeBlend > 0.5f)) return "cascadeLambda above 1 or cascadeBlend above 0.5 (or NaN/Inf)";
    if ((in.cascades < 0) || (in.cascades > RBL__MAX_CASCADES)) return "cascades outside 0..4";
    if (in.omni && (in.cascades > 1)) return "omni and cascades together";
    int tiles = in.omni? 3 : ((in.cascades > 1)? in.cascades : 1), side = (in.size == 0)? 1024 : in.size;
    if ((side < 16) || (side*tiles > RBL_MAX_TARGET_SIZE)) return "size x tiles across (3 omni, the cascades) above RBL_MAX_TARGET_SIZE";
    out->omni = in.omni;
    out->cascades = (in.cascades > 1)? in.cascades : 0;
    out->cascadeLambda = (in.cascadeLambda == 0.0f)? 0.75f : ((in.cascadeLambda < 0.0f)? 0.0f : in.cascadeLambda);
    out->cascadeBlend = (in.cascadeBlend == 0.0f)? 0.1f : ((in.cascadeBlend < 0.0f)? 0.0f : in.cascadeBlend);
    out->size = (in.size == 0)? 1024 : in.size;
    out->constantBias = (in.constantBias == 0.0f)? 0.2f : ((in.constantBias < 0.0f)? 0.0f : in.constantBias);
    out->slopeBias = (in.slopeBias == 0.0f)? 0.1f : ((in.slopeBias < 0.0f)? 0.0f : in.slopeBias);
    out->normalBias = (in.normalBias == 0.0f)? 0.25f : ((in.normalBias < 0.0f)? 0.0f : in.normalBias);
    out->minCastAngle = (in.minCastAngle == 0.0f)? 30.0f : ((in.minCastAngle < 0.0f)? 0.0f : in.minCastAngle);
    out->faceCamera = in.faceCamera;
    out->selfShadow = in.selfShadow;
    // The nearest blended caster's distance is kept by min blending (EXT_blend_minmax on ES 2: not asked for)
    if (in.transmittance && (rlGetVersion() == RL_OPENGL_ES_20)) return "transmittance needs min blending (GL, ES 3, WebGL2)";
    if (in.transmittance && (in.omni || (in.cascades > 1))) return "transmittance works on single maps (not omni or cascaded ones)";
    out->transmittance = in.transmittance;
    return NULL;
}

// The caster programs (vertex buffers, instanced where the context instances): one more holder
// each, or none on failure
static bool rbl__acquireCasters(void)
{
    rbl__Program *got[2] = { NULL, NULL };
    for (int instanced = 0; instanced < ((rbl__glsl() >= 300)? 2 : 1); instanced++)
    {
        RblLitShaderDesc desc, normalised;
        memset(&desc, 0, sizeof(desc));
        desc.instanced = (instanced == 1);
        rbl__normaliseLitDesc(desc, &normalised);
        rbl__ProgramKey key;
        rbl__keyFromDesc(&normalised, RBL__KIND_CASTER, 0, &key);
        got[instanced] = rbl__acquireProgram(&key);
        if (got[instanced] == NULL)
        {
            if (instanced == 1) rbl__releaseProgram(got[0]->shader.id, RBL__KIND_CASTER);
            return false;
        }
    }
    rbl__state.casterIds[0] = got[0]->shader.id;
    rbl__state.casterIds[1] = (got[1] != NULL)? got[1]->shader.id : 0;
    return true;
}

RblShadowMap RblLoadShadowMap(RblShadowDesc desc)
{
    RblShadowMap map;
    memset(&map, 0, sizeof(map));
    const char *bad = rbl__normaliseShadowDesc(desc, &map.desc);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadShadowMap: %s", bad); memset(&map, 0, sizeof(map)); return map; }
    map.state = (rbl__ShadowMapState *)RBL_CALLOC(1, sizeof(rbl__ShadowMapState));
    if ((map.state == NULL) || ((map.id = rbl__liveAdd(map.state)) == 0))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadShadowMap: out of memory");
        RBL_FREE(map.state);
        memset(&map, 0, sizeof(map));
        return map;
    }
    if (!rbl__acquireCasters())
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadShadowMap: caster programs unavailable (%s)", rbl__state.problem);
        rbl__liveRemove(map.id);
        RBL_FREE(map.state);
        memset(&map, 0, sizeof(map));
        return map;
    }
    map.size = map.desc.size;
    map.light = -1;
    // Tiles side by side in one target: cube faces 3 x 2 (+X -X +Y / -Y +Z -Z), cascades in a row
    map.state->kind = map.desc.omni? RBL__SHADOW_OMNI : ((map.desc.cascades > 1)? map.desc.cascades : RBL__SHADOW_SINGLE);
    map.state->cols = map.desc.omni? 3 : ((map.desc.cascades > 1)? map.desc.cascades : 1);
    map.state->rows = map.desc.omni? 2 : 1;
    int width = map.size*map.state->cols, height = map.size*map.state->rows;
    unsigned int callerTarget = rbl__activeFramebuffer();
    map.depth.id = rlLoadTextureDepth(width, height, false);
    map.depth.width = width; map.depth.height = height; map.depth.mipmaps = 1;
    bool ok = (map.depth.id != 0);
    if (ok && !map.desc.selfShadow)
    {
        // The casters target: what receivers sample (distance code and identity, unfiltered)
        map.casters.id = rlLoadTexture(NULL, width, height, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8, 1);
        map.casters.width = width; map.casters.height = height; map.casters.mipmaps = 1; map.casters.format = PIXELFORMAT_UNCOMPRESSED_R8G8B8A8;
        ok = (map.casters.id != 0);
        if (ok)
        {
            rlTextureParameters(map.casters.id, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
            rlTextureParameters(map.casters.id, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
            rlTextureParameters(map.casters.id, RL_TEXTURE_WRAP_S, RL_TEXTURE_WRAP_CLAMP);
            rlTextureParameters(map.casters.id, RL_TEXTURE_WRAP_T, RL_TEXTURE_WRAP_CLAMP);
        }
    }
    if (ok)
    {
        map.state->id = rlLoadFramebuffer();
        rlFramebufferAttach(map.state->id, map.depth.id, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_TEXTURE2D, 0);
        if (map.casters.id != 0) rlFramebufferAttach(map.state->id, map.casters.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
        ok = (map.state->id != 0) && rlFramebufferComplete(map.state->id);
    }
    if (ok && map.desc.transmittance)
    {
        // The transmittance target: blended casters multiply its rgb (cleared to 1) and keep the
        // nearest one's distance code in a (min), depth-tested against the opaque casters' depth
        map.transmittance.id = rlLoadTexture(NULL, map.size, map.size, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8, 1);
        map.transmittance.width = map.size; map.transmittance.height = map.size; map.transmittance.mipmaps = 1;
        map.transmittance.format = PIXELFORMAT_UNCOMPRESSED_R8G8B8A8;
        ok = (map.transmittance.id != 0);
        if (ok)
        {
            rlTextureParameters(map.transmittance.id, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
            rlTextureParameters(map.transmittance.id, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
            rlTextureParameters(map.transmittance.id, RL_TEXTURE_WRAP_S, RL_TEXTURE_WRAP_CLAMP);
            rlTextureParameters(map.transmittance.id, RL_TEXTURE_WRAP_T, RL_TEXTURE_WRAP_CLAMP);
            map.state->blendId = rlLoadFramebuffer();
            rlFramebufferAttach(map.state->blendId, map.depth.id, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_TEXTURE2D, 0);
            rlFramebufferAttach(map.state->blendId, map.transmittance.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
            ok = (map.state->blendId != 0) && rlFramebufferComplete(map.state->blendId);
        }
    }
    rbl__restoreTarget(callerTarget);
    if (!ok)
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadShadowMap: %ix%i depth target unavailable", width, height);
        RblUnloadShadowMap(&map);
        return map;
    }
    TraceLog(LOG_INFO, "RBL: shadow map %ix%i loaded (%s%s%s)", width, height, map.desc.selfShadow? "depth" : "depth + RGBA8 casters target",
             map.desc.omni? ", six cube faces" : ((map.desc.cascades > 1)? ", cascades" : ""), map.desc.transmittance? " + RGBA8 transmittance target" : "");
    return map;
}

bool RblIsShadowMapValid(RblShadowMap map)
{
    // Membership first: a stale copy's state (its map unloaded) is never read
    return rbl__isLive(map.id, map.state) && (map.state->id != 0) && (map.depth.id != 0) && (map.size > 0) && ((map.casters.id != 0) != map.desc.selfShadow) &&
           ((map.transmittance.id != 0) == map.desc.transmittance);
}

void RblUnloadShadowMap(RblShadowMap *map)
{
    if (!rbl__unloadable(map, (map != NULL)? map->id : 0, (map != NULL)? map->state : NULL, "RblUnloadShadowMap", "shadow map")) { if (map != NULL) memset(map, 0, sizeof(*map)); return; }
    if (map->state->begun) { TraceLog(LOG_WARNING, "RBL: RblUnloadShadowMap: its shadow pass is in progress (RblEndShadowMap first)"); return; }
    rbl__dropSceneShadow(map->id);
    if (rbl__glUsable() && (map->state->blendId != 0))
    {
        // The depth texture is the other framebuffer's to delete: detached first
        rlFramebufferAttach(map->state->blendId, 0, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_TEXTURE2D, 0);
        rlUnloadFramebuffer(map->state->blendId);                          // deletes the transmittance target
    }
    else if (rbl__glUsable() && (map->transmittance.id != 0)) rlUnloadTexture(map->transmittance.id);
    if (!rbl__glUsable()) {}                                                // gone with the context
    else if (map->state->id != 0) rlUnloadFramebuffer(map->state->id);    // deletes its depth texture (and casters target) too
    else
    {
        if (map->depth.id != 0) rlUnloadTexture(map->depth.id);
        if (map->casters.id != 0) rlUnloadTexture(map->casters.id);
    }
    rbl__releaseProgram(rbl__state.casterIds[0], RBL__KIND_CASTER);        // the two casters it acquired
    if (rbl__state.casterIds[1] != 0) rbl__releaseProgram(rbl__state.casterIds[1], RBL__KIND_CASTER);
    if (rbl__findCaster(rbl__state.casterIds[0]) == NULL)                 // the last map: the on-demand casters go too
    {
        for (int k = 2; k < 7; k++)                                          // skinned, cross-fade and blended casters
        {
            if (rbl__state.casterIds[k] != 0) rbl__releaseProgram(rbl__state.casterIds[k], RBL__KIND_CASTER);
            rbl__state.casterIds[k] = 0;
        }
    }
    rbl__liveRemove(map->id);
    RBL_FREE(map->state);
    memset(map, 0, sizeof(*map));
    rbl__tidyAfterClose();
}

// raymath's MatrixOrtho / MatrixFrustum, in raylib's layout
static Matrix rbl__ortho(double l, double r, double b, double t, double n, double f)
{
    Matrix m;
    memset(&m, 0, sizeof(m));
    m.m0 = (float)(2.0/(r - l)); m.m5 = (float)(2.0/(t - b)); m.m10 = (float)(-2.0/(f - n));
    m.m12 = (float)(-(l + r)/(r - l)); m.m13 = (float)(-(t + b)/(t - b)); m.m14 = (float)(-(f + n)/(f - n)); m.m15 = 1.0f;
    return m;
}

static Matrix rbl__frustum(double l, double r, double b, double t, double n, double f)
{
    Matrix m;
    memset(&m, 0, sizeof(m));
    m.m0 = (float)(2.0*n/(r - l)); m.m5 = (float)(2.0*n/(t - b)); m.m8 = (float)((r + l)/(r - l)); m.m9 = (float)((t + b)/(t - b));
    m.m10 = (float)(-(f + n)/(f - n)); m.m11 = -1.0f; m.m14 = (float)(-2.0*f*n/(f - n));
    return m;
}

// Texels each omni face and cascade keeps beyond what it must cover: the widest PCF footprint's
// half and the normal offset stay inside the tile, so a lookup never reads a neighbour's texels
#define RBL__SHADOW_GUARD (RBL_SHADOW_MAX_FILTER/2 + 2)

// Omni face f (+X -X +Y -Y +Z -Z, tile (f % 3, f / 3)): its axis away from the light, up (+Z for
// the Y faces, else +Y) and right = axis x up; shadows.glsl picks and builds the same
static void rbl__cubeFace(int f, Vector3 *axis, Vector3 *up, Vector3 *right)
{
    float s = (f & 1)? -1.0f : 1.0f;
    *axis = rbl__v3((f/2 == 0)? s : 0.0f, (f/2 == 1)? s : 0.0f, (f/2 == 2)? s : 0.0f);
    *up = (f/2 == 1)? rbl__v3(0.0f, 0.0f, 1.0f) : rbl__v3(0.0f, 1.0f, 0.0f);
    *right = rbl__cross(*axis, *up);
}

int RblShadowMapPasses(RblShadowMap map)
{
    if (!RblIsShadowMapValid(map)) return 0;
    return map.desc.omni? 6 : ((map.desc.cascades > 1)? map.desc.cascades : 1);
}

bool RblBeginShadowMap(RblShadowMap *map, const RblScene *scene, int lightIndex, Vector3 focusCenter, float focusRadius)
{
    return RblBeginShadowMapPass(map, scene, lightIndex, 0, focusCenter, focusRadius);
}

bool RblBeginShadowMapPass(RblShadowMap *map, const RblScene *scene, int lightIndex, int pass, Vector3 focusCenter, float focusRadius)
{
    const char *bad = NULL;
    float p[4], c[4], spot[4], k[3];
    const RblLight *lights = (scene != NULL)? scene->lights : NULL;
    int kind = ((map != NULL) && RblIsShadowMapValid(*map))? map->state->kind : RBL__SHADOW_SINGLE;
    int type = ((lights != NULL) && (lightIndex >= 0) && (lightIndex < scene->lightCount))? lights[lightIndex].type : -1;
    if ((map == NULL) || !RblIsShadowMapValid(*map)) bad = "invalid shadow map";
    else if (map->state->begun || (rbl__state.shadowPass != NULL)) bad = "a shadow pass is already in progress";
    else if (rbl__state.gbufferPass != NULL) bad = "inside a G-buffer pass";
    else if ((scene == NULL) || (lights == NULL) || (lightIndex < 0) || (lightIndex >= scene->lightCount)) bad = "no scene, or lightIndex outside 0..scene->lightCount-1";
    else if ((pass < 0) || (pass >= RblShadowMapPasses(*map))) bad = "pass outside 0..RblShadowMapPasses-1";
    else if ((type != RBL_LIGHT_DIRECTIONAL) && (type != RBL_LIGHT_SPOT) && (type != RBL_LIGHT_POINT)) bad = "only directional, spot and point lights cast shadows";
    else if ((type == RBL_LIGHT_POINT) != (kind == RBL__SHADOW_OMNI)) bad = "point lights cast through omni maps (RblShadowDesc.omni), other lights through other maps";
    else if ((kind > RBL__SHADOW_OMNI) && (type != RBL_LIGHT_DIRECTIONAL)) bad = "cascaded maps shadow directional lights only";
    else if ((kind > RBL__SHADOW_OMNI) && !map->state->fitted) bad = "cascaded map not fitted to a camera (RblFitShadowCascades first)";
    else if ((bad = rbl__packLight(&lights[lightIndex], p, c, spot, k)) != NULL) {}
    else if (!rbl__bounded3(focusCenter) || !rbl__finite(focusRadius) || (focusRadius < 0.0f) || (focusRadius > 1e17f)) bad = "focus centre not finite or >= 1.15e18, radius outside 0..1e17";
    else if ((kind == RBL__SHADOW_SINGLE) && (type == RBL_LIGHT_DIRECTIONAL) && !(focusRadius > 0.0f)) bad = "a directional shadow needs a focus radius > 0";
    else if ((type == RBL_LIGHT_SPOT) && (lights[lightIndex].outerAngle > 80.0f)) bad = "spot shadows need outerAngle <= 80 degrees";
    else if ((type != RBL_LIGHT_DIRECTIONAL) && !(lights[lightIndex].range > 0.0f) && !(focusRadius > 0.0f)) bad = "a spot or point shadow without a range needs a focus radius > 0";
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblBeginShadowMapPass: %s", bad); return false; }

    const RblLight *light = &lights[lightIndex];
    Vector3 dir = rbl__v3(-p[0], -p[1], -p[2]);            // directional: p holds the unit vector toward the light
    if (light->type == RBL_LIGHT_SPOT) rbl__normalizeTo(light->direction, &dir);
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.up = rbl__v3(0.0f, 1.0f, 0.0f);                     // RblGetCameraFrame falls back when the light is vertical
    double size = (double)map->size;
    Matrix projection;
    rbl__ShadowMapState *st = map->state;
    RblCameraFrame passView;                                // the camera the pass renders with (omni: the face's)
    if (kind > RBL__SHADOW_OMNI)
    {
        // Cascade `pass`: one light frame and depth range for all (every cascade's sphere, casters up
        // to 2r toward the light), each window snapped to whole texels of its own world-fixed grid
        int n = kind;
        double nearD = 1e300, farD = -1e300;
        for (int i = 0; i < n; i++)
        {
            double along = dir.x*st->fitCenter[i][0] + dir.y*st->fitCenter[i][1] + dir.z*st->fitCenter[i][2];
            nearD = fmin(nearD, along - 2.0*st->fitRadius[i]); farD = fmax(farD, along + st->fitRadius[i]);
        }
        const double *last = st->fitCenter[n - 1];
        double back = dir.x*last[0] + dir.y*last[1] + dir.z*last[2] - nearD;
        cam.target = rbl__v3((float)last[0], (float)last[1], (float)last[2]);
        cam.position = rbl__v3((float)(last[0] - dir.x*back), (float)(last[1] - dir.y*back), (float)(last[2] - dir.z*back));
        cam.projection = CAMERA_ORTHOGRAPHIC;
        st->lightView = rbl__cameraFrame(cam);
        const RblCameraFrame *f = &st->lightView;
        double ex = rbl__dot(f->right, cam.position), ey = rbl__dot(f->up, cam.position), ez = rbl__dot(rbl__neg(f->back), cam.position);
        double range = farD - ez;
        for (int i = 0; i < n; i++)
        {
            double r = st->fitRadius[i], texel = 2.0*r/(size - 2.0*RBL__SHADOW_GUARD);
            double cx = f->right.x*st->fitCenter[i][0] + f->right.y*st->fitCenter[i][1] + f->right.z*st->fitCenter[i][2];
            double cy = f->up.x*st->fitCenter[i][0] + f->up.y*st->fitCenter[i][1] + f->up.z*st->fitCenter[i][2];
            double left = (floor((cx - r)/texel) - RBL__SHADOW_GUARD)*texel, bottom = (floor((cy - r)/texel) - RBL__SHADOW_GUARD)*texel;
            double inv = 1.0/(texel*size);
            st->tiles[i][0] = (float)inv; st->tiles[i][1] = (float)(-left*inv); st->tiles[i][2] = (float)(-bottom*inv); st->tiles[i][3] = (float)st->split[i + 1];
            if (i == pass)
            {
                st->texelWorld = (float)texel;
                projection = rbl__ortho(left - ex, left - ex + texel*size, bottom - ey, bottom - ey + texel*size, 0.0, range);
            }
        }
        Vector3 a = rbl__neg(f->back);
        float rows[3][4] = { { f->right.x, f->right.y, f->right.z, 0.0f }, { f->up.x, f->up.y, f->up.z, 0.0f },
                             { (float)(a.x/range), (float)(a.y/range), (float)(a.z/range), (float)(-ez/range) } };
        memcpy(st->cascadeRows, rows, sizeof(rows));       // [3] the camera plane, from the fit
        st->nearPlane = 0.0f; st->farPlane = (float)range;
        passView = st->lightView;
    }
    else if (light->type == RBL_LIGHT_DIRECTIONAL)
    {
        // Orthographic over the focus sphere, eye 2r before its centre: casters up to 2r toward the light
        // from the centre and receivers up to r beyond it. The window moves in whole texels of a grid
        // fixed in the world, so shadow edges do not crawl while the focus follows the camera.
        double r = focusRadius, texel = 2.0*r/(size - 1.0);
        cam.position = rbl__v3(focusCenter.x - dir.x*2.0f*focusRadius, focusCenter.y - dir.y*2.0f*focusRadius, focusCenter.z - dir.z*2.0f*focusRadius);
        cam.target = focusCenter;
        cam.projection = CAMERA_ORTHOGRAPHIC;          // parallel rays: light-facing casters face the direction
        map->state->lightView = rbl__cameraFrame(cam);
        double ex = rbl__dot(map->state->lightView.right, cam.position), ey = rbl__dot(map->state->lightView.up, cam.position);
        double cx = rbl__dot(map->state->lightView.right, focusCenter), cy = rbl__dot(map->state->lightView.up, focusCenter);
        double left = floor((cx - r)/texel)*texel - ex, bottom = floor((cy - r)/texel)*texel - ey;
        map->state->nearPlane = 0.0f; map->state->farPlane = (float)(3.0*r);
        map->state->texelWorld = (float)texel;
        projection = rbl__ortho(left, left + texel*size, bottom, bottom + texel*size, 0.0, 3.0*r);
        passView = st->lightView;
    }
    else if (light->type == RBL_LIGHT_POINT)
    {
        // Cube face `pass`: a 90-degree perspective widened by the guard texels on each side (tan t);
        // billboards turn in one frame for all six faces (toward the light), so a card drawn into two
        // faces is the same card in both
        double farPlane = (light->range > 0.0f)? light->range : sqrt(rbl__len2(rbl__sub(focusCenter, light->position))) + focusRadius;
        double nearPlane = farPlane*1e-3, t = size/(size - 2.0*RBL__SHADOW_GUARD);
        Vector3 axis, up, right;
        rbl__cubeFace(pass, &axis, &up, &right);
        memset(&passView, 0, sizeof(passView));
        passView.eye = light->position; passView.right = right; passView.up = up; passView.back = rbl__neg(axis);
        memset(&st->lightView, 0, sizeof(st->lightView));
        st->lightView.eye = light->position;
        st->lightView.right = rbl__v3(1.0f, 0.0f, 0.0f); st->lightView.up = rbl__v3(0.0f, 1.0f, 0.0f); st->lightView.back = rbl__v3(0.0f, 0.0f, 1.0f);
        st->nearPlane = (float)nearPlane; st->farPlane = (float)farPlane;
        st->texelWorld = (float)(2.0*t/size);
        st->tiles[0][0] = light->position.x; st->tiles[0][1] = light->position.y; st->tiles[0][2] = light->position.z; st->tiles[0][3] = (float)t;
        projection = rbl__frustum(-t*nearPlane, t*nearPlane, -t*nearPlane, t*nearPlane, nearPlane, farPlane);
    }
    else
    {
        // Perspective over the outer cone; depth range = the light's range (or out to the focus sphere)
        double outer = ((light->outerAngle == 0.0f)? 30.0 : light->outerAngle)*PI/180.0;
        double farPlane = (light->range > 0.0f)? light->range : sqrt(rbl__len2(rbl__sub(focusCenter, light->position))) + focusRadius;
        double nearPlane = farPlane*1e-3, t = tan(outer);
        cam.position = light->position;
        cam.target = rbl__v3(light->position.x + dir.x, light->position.y + dir.y, light->position.z + dir.z);
        map->state->lightView = rbl__cameraFrame(cam);
        map->state->nearPlane = (float)nearPlane; map->state->farPlane = (float)farPlane;
        map->state->texelWorld = (float)(2.0*t/size);
        projection = rbl__frustum(-t*nearPlane, t*nearPlane, -t*nearPlane, t*nearPlane, nearPlane, farPlane);
        passView = st->lightView;
    }
    Matrix bias = rbl__identity();
    bias.m0 = bias.m5 = bias.m10 = 0.5f; bias.m12 = bias.m13 = bias.m14 = 0.5f;
    map->state->view = rbl__viewMatrix(&passView);
    map->state->projection = projection;
    map->state->matrix = rbl__matMul(rbl__matMul(map->state->view, projection), bias);
    map->light = lightIndex;
    map->state->lightType = light->type;
    st->pass = pass;

    rlDrawRenderBatchActive();
    for (int u = 0; u < RBL_MAX_SHADOWS; u++) { rlActiveTextureSlot(RBL_SHADOW_TEXTURE_UNIT + u); rlDisableTexture(); }   // nothing may sample the target
    rlActiveTextureSlot(0);
    map->state->savedView = rlGetMatrixModelview();
    map->state->savedProjection = rlGetMatrixProjection();
    map->state->savedFramebuffer = rbl__activeFramebuffer();
    int x0 = (pass%st->cols)*map->size, y0 = (pass/st->cols)*map->size;
    rlViewport(x0, y0, map->size, map->size);
    rlEnableDepthMask();
    if (map->state->blendId != 0)
    {
        rlEnableFramebuffer(map->state->blendId);
        rlClearColor(255, 255, 255, 255);   // transmittance 1, nearest blended caster beyond the far plane
        rlClearScreenBuffers();
    }
    rlEnableFramebuffer(map->state->id);
    rlEnableDepthTest();
    rlClearColor(255, 255, 0, 0);           // casters target: distance code 1 (nothing), identity 0
    bool tiled = (st->cols*st->rows > 1);
    if (tiled) { rlEnableScissorTest(); rlScissor(x0, y0, map->size, map->size); }      // this tile only
    rlClearScreenBuffers();
    if (tiled) rlDisableScissorTest();
    rlDisableColorBlend();                  // the identity's low byte is the target's alpha
    rlDisableBackfaceCulling();             // a billboard facing the viewer may show the light its back
    rlSetMatrixProjection(projection);
    rlSetMatrixModelview(map->state->view);
    map->state->begun = true;
    rbl__state.shadowPassMap = *map;
    rbl__state.shadowPass = &rbl__state.shadowPassMap;
    rbl__state.cast = rbl__castOf(map);
    return true;
}

void RblEndShadowMap(RblShadowMap *map)
{
    if ((map == NULL) || !rbl__isLive(map->id, map->state) || !map->state->begun) { TraceLog(LOG_WARNING, "RBL: RblEndShadowMap: no shadow pass of this map in progress"); return; }
    if (map->state->blending) RblEndShadowBlend();
    rlDrawRenderBatchActive();
    rbl__restoreTarget(map->state->savedFramebuffer);      // e.g. inside BeginTextureMode
    rlSetMatrixProjection(map->state->savedProjection);
    rlSetMatrixModelview(map->state->savedView);
    rlEnableBackfaceCulling();
    rlDisableDepthTest();
    rlEnableColorBlend();                   // raylib's default
    map->state->begun = false;
    rbl__state.shadowPass = NULL;
    memset(&rbl__state.cast, 0, sizeof(rbl__state.cast));
    rbl__bindSceneShadows();        // the pass unbound the receivers' units
}

bool RblBeginShadowBlend(bool coloured)
{
    RblShadowMap *map = rbl__state.shadowPass;
    const char *bad = (map == NULL)? "outside a shadow pass" : (map->state->blendId == 0)? "the map has no transmittance target (RblShadowDesc.transmittance)" :
                      map->state->blending? "already blending (RblEndShadowBlend first)" : NULL;
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblBeginShadowBlend: %s", bad); return false; }
    rlDrawRenderBatchActive();
    rlEnableFramebuffer(map->state->blendId);
    // Behind the opaque casters nothing counts (depth test, no writes); rgb multiplies by each
    // caster's transmittance, a keeps the smallest distance code (0x0300 GL_SRC_COLOR, 0x8006 add, 0x8007 min)
    rlDisableDepthMask();
    rlSetBlendFactorsSeparate(0, 0x0300, 1, 1, 0x8006, 0x8007);
    rlSetBlendMode(RL_BLEND_CUSTOM_SEPARATE);
    rlEnableColorBlend();
    map->state->blending = true;
    map->state->coloured = coloured;
    // Every texel with any coverage casts (the material's cutoff is for opaque casters)
    map->state->savedAlphaBand = rbl__state.alphaBand;
    rbl__state.alphaBand.x = 1.0f/512.0f; rbl__state.alphaBand.y = 2.0f;
    return true;
}

void RblEndShadowBlend(void)
{
    RblShadowMap *map = rbl__state.shadowPass;
    if ((map == NULL) || !map->state->blending) { TraceLog(LOG_WARNING, "RBL: RblEndShadowBlend: no blended casters in progress"); return; }
    rlDrawRenderBatchActive();
    rlSetBlendMode(RL_BLEND_ALPHA);
    rlDisableColorBlend();
    rlEnableDepthMask();
    rlEnableFramebuffer(map->state->id);
    rbl__state.alphaBand = map->state->savedAlphaBand;
    map->state->blending = false;
}

bool RblShadowFocusFromCamera(Camera3D camera, float aspect, float nearDistance, float farDistance, Vector3 *center, float *radius)
{
    if ((center == NULL) || (radius == NULL) || !rbl__cameraOk(camera) || !rbl__finite(aspect) || !(aspect > 0.0f) || !(aspect < 1e6f) ||
        !rbl__finite(nearDistance) || !rbl__finite(farDistance) || !(nearDistance >= 0.0f) || !(farDistance > nearDistance) || !(farDistance < 1e17f))
    {
        TraceLog(LOG_WARNING, "RBL: RblShadowFocusFromCamera: needs 0 <= near < far < 1e17, 0 < aspect < 1e6, a valid camera (0 < fovy < 180 perspective), finite values");
        return false;
    }
    RblCameraFrame v = rbl__cameraFrame(camera);
    // Half-diagonal of the slice's cross-section at distance d: perspective grows with d, orthographic not
    double n = nearDistance, f = farDistance, k = sqrt(1.0 + (double)aspect*aspect);
    double rn, rf;
    if (camera.projection == CAMERA_ORTHOGRAPHIC) rn = rf = 0.5*camera.fovy*k;
    else { double t = tan(camera.fovy*0.5*PI/180.0); rn = n*t*k; rf = f*t*k; }
    // Smallest sphere centred on the axis through both end caps: equal distance to both rims, kept in [n, f]
    double c = (f*f + rf*rf - n*n - rn*rn)/(2.0*(f - n));
    if (c < n) c = n;
    if (c > f) c = f;
    double r = fmax(sqrt((c - n)*(c - n) + rn*rn), sqrt((f - c)*(f - c) + rf*rf));
    Vector3 cc = rbl__v3(camera.position.x - v.back.x*(float)c, camera.position.y - v.back.y*(float)c, camera.position.z - v.back.z*(float)c);
    if (!rbl__bounded3(cc) || !(r < 1e17))
    {
        TraceLog(LOG_WARNING, "RBL: RblShadowFocusFromCamera: the focus sphere overflows (radius %g)", r);
        return false;
    }
    *center = cc;
    *radius = (float)r;
    return true;
}

// Smallest sphere holding the slice near..far of a camera's view (double): centred on the axis,
// equally far from both end caps' rims, kept between the caps. A rotation or pan of the camera
// moves it without changing its radius (what lets cascades snap to texels without shimmer)
static void rbl__sliceSphere(const RblCameraFrame *v, Camera3D camera, double aspect, double n, double f, double centre[3], double *radius)
{
    double k = sqrt(1.0 + aspect*aspect), rn, rf;
    if (camera.projection == CAMERA_ORTHOGRAPHIC) rn = rf = 0.5*camera.fovy*k;
    else { double t = tan(camera.fovy*0.5*PI/180.0); rn = n*t*k; rf = f*t*k; }
    double c = (f*f + rf*rf - n*n - rn*rn)/(2.0*(f - n));
    c = fmin(fmax(c, n), f);
    *radius = fmax(sqrt((c - n)*(c - n) + rn*rn), sqrt((f - c)*(f - c) + rf*rf));
    centre[0] = camera.position.x - v->back.x*c; centre[1] = camera.position.y - v->back.y*c; centre[2] = camera.position.z - v->back.z*c;
}

bool RblFitShadowCascades(RblShadowMap *map, Camera3D camera, float aspect, float nearDistance, float farDistance)
{
    const char *bad = NULL;
    if ((map == NULL) || !RblIsShadowMapValid(*map) || (map->state->kind <= RBL__SHADOW_OMNI)) bad = "not a cascaded shadow map (RblShadowDesc.cascades 2..4)";
    else if (map->state->begun) bad = "its shadow pass is in progress";
    else if (!rbl__cameraOk(camera) || !rbl__finite(aspect) || !(aspect > 0.0f) || !(aspect < 1e6f)) bad = "needs a valid camera (0 < fovy < 180 perspective) and 0 < aspect < 1e6";
    else if (!rbl__finite(nearDistance) || !rbl__finite(farDistance) || !(nearDistance > 0.0f) || !(farDistance > nearDistance) || !(farDistance < 1e17f)) bad = "needs 0 < near < far < 1e17";
    else if (!rbl__bounded3(camera.position)) bad = "camera position not finite or >= 1.15e18";
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblFitShadowCascades: %s", bad); return false; }
    rbl__ShadowMapState *st = map->state;
    int n = st->kind;
    double nd = nearDistance, fd = farDistance, lambda = map->desc.cascadeLambda;
    // Practical split: a mix of the logarithmic split (even texel density in depth) and the uniform one
    for (int i = 0; i <= n; i++)
    {
        double x = (double)i/n;
        st->split[i] = (i == 0)? nd : ((i == n)? fd : lambda*nd*pow(fd/nd, x) + (1.0 - lambda)*(nd + (fd - nd)*x));
    }
    // Cascade i covers its slice and, from i = 1, the previous slice's blend band (both lookups of a
    // point in the band land inside their maps)
    RblCameraFrame v = rbl__cameraFrame(camera);
    st->blend = map->desc.cascadeBlend;
    for (int i = 0; i < n; i++)
    {
        double lo = st->split[i];
        if (i > 0) lo -= st->blend*(st->split[i] - st->split[i - 1]);
        rbl__sliceSphere(&v, camera, aspect, lo, st->split[i + 1], st->fitCenter[i], &st->fitRadius[i]);
    }
    st->fitView = v;
    st->fitOrthographic = (camera.projection == CAMERA_ORTHOGRAPHIC);
    st->fitTan = st->fitOrthographic? 0.5*camera.fovy : tan(camera.fovy*0.5*PI/180.0);
    st->fitAspect = aspect;
    Vector3 fwd = rbl__neg(v.back);
    st->cascadeRows[3][0] = fwd.x; st->cascadeRows[3][1] = fwd.y; st->cascadeRows[3][2] = fwd.z; st->cascadeRows[3][3] = -rbl__dot(fwd, camera.position);
    st->fitted = true;
    return true;
}

Color RblShadowCascadeColor(int cascade)
{
    const Color colors[4] = { { 230, 41, 55, 255 }, { 0, 228, 48, 255 }, { 0, 121, 241, 255 }, { 253, 249, 0, 255 } };
    return ((cascade >= 0) && (cascade < 4))? colors[cascade] : GRAY;
}

// The debug view: per cascade the slice of the fitted camera's view it serves (near and far
// rectangles and the edges between; from cascade 1 the near one widened by the blend band) and the
// light-space box its pass rendered (the snapped window x the shared depth range), as lines
void RblDrawShadowCascades(RblShadowMap map)
{
    if (!RblIsShadowMapValid(map) || (map.state->kind <= RBL__SHADOW_OMNI) || !map.state->fitted || (map.state->tiles[0][0] == 0.0f))
    {
        TraceLog(LOG_WARNING, "RBL: RblDrawShadowCascades: needs a cascaded map fitted and rendered (RblFitShadowCascades, its passes)");
        return;
    }
    const rbl__ShadowMapState *st = map.state;
    const RblCameraFrame *v = &st->fitView, *l = &st->lightView;
    Vector3 a = rbl__neg(l->back);
    for (int c = 0; c < st->kind; c++)
    {
        Color col = RblShadowCascadeColor(c);
        Vector3 q[8];
        for (int k = 0; k < 8; k++)
        {
            double d = (k & 4)? st->split[c + 1] : ((c > 0)? st->split[c] - st->blend*(st->split[c] - st->split[c - 1]) : st->split[c]);
            double hy = st->fitOrthographic? st->fitTan : d*st->fitTan, hx = hy*st->fitAspect;
            double sx = (k & 1)? hx : -hx, sy = (k & 2)? hy : -hy;
            q[k] = rbl__v3((float)(v->eye.x - v->back.x*d + v->right.x*sx + v->up.x*sy), (float)(v->eye.y - v->back.y*d + v->right.y*sx + v->up.y*sy),
                           (float)(v->eye.z - v->back.z*d + v->right.z*sx + v->up.z*sy));
        }
        // The window in world space: (x, y) along right and up, depth along the light's axis
        double inv = st->tiles[c][0], left = -st->tiles[c][1]/inv, bottom = -st->tiles[c][2]/inv, side = 1.0/inv;
        double z0 = -(double)st->cascadeRows[2][3]*st->farPlane, z1 = z0 + st->farPlane;
        Vector3 b[8];
        for (int k = 0; k < 8; k++)
        {
            double x = left + ((k & 1)? side : 0.0), y = bottom + ((k & 2)? side : 0.0), z = (k & 4)? z1 : z0;
            b[k] = rbl__v3((float)(l->right.x*x + l->up.x*y + a.x*z), (float)(l->right.y*x + l->up.y*y + a.y*z), (float)(l->right.z*x + l->up.z*y + a.z*z));
        }
        const int edges[12][2] = { { 0, 1 }, { 1, 3 }, { 3, 2 }, { 2, 0 }, { 4, 5 }, { 5, 7 }, { 7, 6 }, { 6, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
        for (int e = 0; e < 12; e++)
        {
            DrawLine3D(q[edges[e][0]], q[edges[e][1]], col);
            DrawLine3D(b[edges[e][0]], b[edges[e][1]], Fade(col, 0.5f));
        }
    }
}

// What shadows.glsl reads of one map: matrix (16), params (4), bias (4), axes (8), tiles (16).
// params.y = format (perspective + 2 for the casters target) + 4 x kind (0 one map, 1 omni, 2..4 cascades)
static void rbl__shadowUniformData(const RblShadowMap *map, float out[48])
{
    const rbl__ShadowMapState *st = map->state;
    memset(out, 0, 48*sizeof(float));
    if (st->kind > RBL__SHADOW_OMNI) memcpy(out, st->cascadeRows, 16*sizeof(float));   // light frame rows; the camera plane
    else
    {
        // The matrix as four rows (vec4s): rlSetUniformMatrices would transpose on desktop GL and not on ES
        const Matrix *m = &st->matrix;
        const float rows[16] = { m->m0, m->m4, m->m8, m->m12, m->m1, m->m5, m->m9, m->m13, m->m2, m->m6, m->m10, m->m14, m->m3, m->m7, m->m11, m->m15 };
        memcpy(out, rows, sizeof(rows));
    }
    out[16] = st->texelWorld;
    out[17] = ((st->lightType != RBL_LIGHT_DIRECTIONAL)? 1.0f : 0.0f) + ((map->casters.id != 0)? 2.0f : 0.0f) + 4.0f*(float)st->kind;
    out[18] = st->nearPlane; out[19] = st->farPlane;
    out[20] = map->desc.constantBias; out[21] = map->desc.slopeBias; out[22] = map->desc.normalBias; out[23] = (float)map->size;
    out[24] = st->lightView.right.x; out[25] = st->lightView.right.y; out[26] = st->lightView.right.z;
    out[27] = (st->kind > RBL__SHADOW_OMNI)? (float)st->split[0] : 0.0f;
    out[28] = st->lightView.up.x; out[29] = st->lightView.up.y; out[30] = st->lightView.up.z;
    out[31] = (st->kind > RBL__SHADOW_OMNI)? (float)st->blend : 0.0f;
    memcpy(&out[32], st->tiles, 16*sizeof(float));
}

// Maps a scene may list: valid, rendered for one of its lights, not being rendered, one per light
static const char *rbl__checkShadowMaps(const RblShadowMap *maps, int count, int lightCount)
{
    if ((count < 0) || (count > RBL_MAX_SHADOWS)) return "shadowMapCount outside 0..RBL_MAX_SHADOWS";
    if ((count > 0) && (maps == NULL)) return "shadowMaps NULL";
    for (int k = 0; k < count; k++)
    {
        if (!RblIsShadowMapValid(maps[k]) || (maps[k].light < 0)) return "a shadow map is invalid or was never rendered (RblBeginShadowMap)";
        if (maps[k].light >= lightCount) return "a shadow map was rendered for a light the scene does not have";
        if (maps[k].state->begun) return "a shadow map is still being rendered (RblEndShadowMap first)";
        for (int j = 0; j < k; j++) if (maps[j].light == maps[k].light) return "two shadow maps shadow the same light";
    }
    return NULL;
}

#if !defined(RBL_NO_ATLAS)
//----------------------------------------------------------------------------------
// Module Functions Definition: sprite-sheet atlases and animation   >>atlas
//----------------------------------------------------------------------------------
// Every format lands in one frame table in TexturePacker's convention: a rotated frame is stored
// turned 90 degrees clockwise in an h x w block; trim and pivot are upright, top-left origin.
// libGDX's counter-clockwise turn is the clockwise one plus a half turn, which is both mirrors: its
// source gets both extents negated (RblBillboardVertices mirrors inside the block). Parsers read
// only inside [text, text + size), bound nesting and counts, and log one line on the first problem.

#define RBL__ATLAS_MAX_DEPTH 64         // JSON nesting
#define RBL__ATLAS_MAX_COORD 65536.0    // texel coordinates and sizes
#define RBL__ATLAS_MAX_PAGES 64         // multipack sheets / libGDX pages / textures[] entries
#define RBL__ATLAS_MAX_REPEAT 65535
#define RBL__ATLAS_MAX_SCALE 65536.0    // meta.scale in 1/65536..65536
#define RBL__ATLAS_MAX_POLYGON 65535    // vertices of one polygon frame (16-bit indices)
#define RBL__ATLAS_PATH 4096            // longest sheet path tried
#if (RBL_MAX_ATLAS_ENTRIES < 1) || (RBL_MAX_ATLAS_ENTRIES > 67108864)
    #error "RBL_MAX_ATLAS_ENTRIES must be in 1..2^26"
#endif

static inline Rectangle rbl__rect(float x, float y, float w, float h) { Rectangle r; r.x = x; r.y = y; r.width = w; r.height = h; return r; }
static inline Vector2 rbl__v2(float x, float y) { Vector2 v; v.x = x; v.y = y; return v; }

// Where a polygon's rows start while the tables grow (its public pointers are set at publication)
typedef struct rbl__AtlasPolyRef { int frame, vertex, index; } rbl__AtlasPolyRef;

typedef struct rbl__AtlasState {
    RblAtlasFrame *frames; int frameCount, frameCap;
    RblAtlasTag *tags; int tagCount, tagCap;
    RblAtlasPage *pages; int pageCount, pageCap;
    RblAtlasSlice *slices; int sliceCount, sliceCap;
    RblAtlasPolygon *polygons; int polygonCount, polygonCap;
    rbl__AtlasPolyRef *polygonRefs; int polygonRefCap;
    Vector2 *polyPoints; int polyPointCount, polyPointCap; // each polygon's vertices, then its uvs
    unsigned short *polyIndices; int polyIndexCount, polyIndexCap;
    rbl__Polygon *polyDraw;                                // Per polygon, what the draw paths read (made at publication)
    Vector2 *polyFrac;                                     // ... its vertices as fractions of the frame's source
    unsigned int *polySlots;                               // ... its slots (4 vertices each), every cut's
    unsigned int polyFirst;                                // Handle of polygon 0 (0 = none registered)
    char **pools; int poolCount, poolCap;                  // name storage: one block per parsed text (and per path), never moved
    char *pool; size_t poolUsed, poolSize;                 // the current block
    int format;
    int ignoredPads;                                       // libGDX pad entries (reported once per load, LOG_INFO)
    char error[3*RBL__ATLAS_PATH + 256];
} rbl__AtlasState;

// Atlases are CPU objects the caller owns past RblClose, named by id like the header's other objects
static bool rbl__atlasLive(const RblAtlas *atlas) { return rbl__isLive(atlas->id, atlas->state); }

static void rbl__atlasError(rbl__AtlasState *s, const char *fmt, const char *detail, long at)
{
    if (s->error[0] != 0) return;           // the first problem is the one reported
    char what[120];
    snprintf(what, sizeof(what), fmt, (detail != NULL)? detail : "");
    if (at >= 0) snprintf(s->error, sizeof(s->error), "%s (byte %ld)", what, at);
    else snprintf(s->error, sizeof(s->error), "%s", what);
}

// The first problem, formatted (at >= 0: the byte it was found at)
static void rbl__atlasErrorf(rbl__AtlasState *s, long at, const char *fmt, ...)
{
    if (s->error[0] != 0) return;
    va_list args;
    va_start(args, fmt);
    int n = vsnprintf(s->error, sizeof(s->error), fmt, args);
    va_end(args);
    if ((at >= 0) && (n >= 0) && ((size_t)n < sizeof(s->error))) snprintf(s->error + n, sizeof(s->error) - (size_t)n, " (byte %ld)", at);
}

static void rbl__atlasFree(rbl__AtlasState *s)
{
    if (s == NULL) return;
    if (s->polyFirst != 0u) rbl__polygonUnregister(s->polyFirst);
    RBL_FREE(s->polyDraw); RBL_FREE(s->polyFrac); RBL_FREE(s->polySlots);
    for (int i = 0; i < s->poolCount; i++) RBL_FREE(s->pools[i]);
    RBL_FREE(s->pools); RBL_FREE(s->frames); RBL_FREE(s->tags); RBL_FREE(s->pages); RBL_FREE(s->slices);
    RBL_FREE(s->polygons); RBL_FREE(s->polygonRefs); RBL_FREE(s->polyPoints); RBL_FREE(s->polyIndices);
    RBL_FREE(s);
}

// Room for `more` elements: the array (grown when short), NULL on failure (the old array kept).
// Every table and the JSON reader's values stop at RBL_MAX_ATLAS_ENTRIES, named in the refusal.
static void *rbl__atlasGrowRaw(rbl__AtlasState *s, void *array, int count, int more, int *cap, size_t elem, const char *what)
{
    if ((more <= *cap - count) && (count <= *cap)) return array;
    if (more > RBL_MAX_ATLAS_ENTRIES - count) { rbl__atlasErrorf(s, -1, "more than %d %s (RBL_MAX_ATLAS_ENTRIES)", RBL_MAX_ATLAS_ENTRIES, what); return NULL; }
    int n = (*cap > 0)? *cap : 16;
    while (n - count < more) n = (n > RBL_MAX_ATLAS_ENTRIES/2)? RBL_MAX_ATLAS_ENTRIES : n*2;
    if (n > RBL_MAX_ATLAS_ENTRIES) n = RBL_MAX_ATLAS_ENTRIES;
    void *p = RBL_REALLOC(array, (size_t)n*elem);
    if (p == NULL) { rbl__atlasErrorf(s, -1, "out of memory"); return NULL; }
    *cap = n;
    return p;
}
#define RBL__ATLAS_GROWN(s, arr, count, more, cap, T, what, onFail) do { void *g_ = rbl__atlasGrowRaw((s), (void *)(arr), (count), (more), &(cap), sizeof(T), (what)); if (g_ == NULL) { onFail; } (arr) = (T *)g_; } while (0)
#define RBL__ATLAS_GROW(s, arr, count, cap, T, what, onFail) RBL__ATLAS_GROWN(s, arr, count, 1, cap, T, what, onFail)

// A name block big enough for every string one text can hold (decoded strings never outgrow the text)
static bool rbl__atlasPoolBegin(rbl__AtlasState *s, size_t bytes)
{
    RBL__ATLAS_GROW(s, s->pools, s->poolCount, s->poolCap, char *, "name blocks", return false);
    char *p = (char *)RBL_MALLOC(bytes);
    if (p == NULL) { rbl__atlasError(s, "out of memory%s", NULL, -1); return false; }
    s->pools[s->poolCount++] = p;
    s->pool = p; s->poolUsed = 0; s->poolSize = bytes;
    return true;
}

static char *rbl__atlasPoolTake(rbl__AtlasState *s, size_t bytes)
{
    if ((s->pool == NULL) || (bytes > s->poolSize - s->poolUsed)) { rbl__atlasError(s, "internal: name storage exhausted%s", NULL, -1); return NULL; }
    char *p = s->pool + s->poolUsed;
    s->poolUsed += bytes;
    return p;
}

static char *rbl__atlasPoolCopy(rbl__AtlasState *s, const char *text, size_t len)
{
    char *p = rbl__atlasPoolTake(s, len + 1);
    if (p == NULL) return NULL;
    memcpy(p, text, len); p[len] = 0;
    return p;
}

// ---- JSON: a node array (values in document order, each knowing where its subtree ends) ----
enum { RBL__J_OBJECT = 1, RBL__J_ARRAY, RBL__J_STRING, RBL__J_NUMBER, RBL__J_TRUE, RBL__J_FALSE, RBL__J_NULL };
typedef struct rbl__JNode {
    int type;
    int start, len;                 // string: between the quotes, raw; number: its text; container: the opening byte
    int next;                       // first node after this subtree (objects: key and value alternate as children)
    int count;                      // children (objects: 2 per member)
} rbl__JNode;

typedef struct rbl__Json {
    const char *text; int size; int pos;
    rbl__JNode *nodes; int count, cap;
    rbl__AtlasState *s;
} rbl__Json;

static void rbl__jsonSkip(rbl__Json *j)
{
    while ((j->pos < j->size) && ((j->text[j->pos] == ' ') || (j->text[j->pos] == '\t') || (j->text[j->pos] == '\n') || (j->text[j->pos] == '\r'))) j->pos++;
}

static int rbl__jsonNode(rbl__Json *j, int type, int start)
{
    RBL__ATLAS_GROW(j->s, j->nodes, j->count, j->cap, rbl__JNode, "JSON values", return -1);
    rbl__JNode *n = &j->nodes[j->count];
    n->type = type; n->start = start; n->len = 0; n->next = j->count + 1; n->count = 0;
    return j->count++;
}

static bool rbl__jsonHex(char c) { return ((c >= '0') && (c <= '9')) || ((c >= 'a') && (c <= 'f')) || ((c >= 'A') && (c <= 'F')); }

static int rbl__jsonValue(rbl__Json *j, int depth);

static int rbl__jsonString(rbl__Json *j)
{
    int start = ++j->pos;   // past the quote
    while (j->pos < j->size)
    {
        unsigned char c = (unsigned char)j->text[j->pos];
        if (c == '"')
        {
            int n = rbl__jsonNode(j, RBL__J_STRING, start);
            if (n < 0) return -1;
            j->nodes[n].len = j->pos - start;
            j->pos++;
            return n;
        }
        if (c < 0x20) { rbl__atlasError(j->s, "JSON: control character in a string%s", NULL, j->pos); return -1; }
        if (c == '\\')
        {
            if (j->pos + 1 >= j->size) break;
            char e = j->text[j->pos + 1];
            if (e == 'u')
            {
                if (j->pos + 5 >= j->size) break;
                for (int k = 2; k < 6; k++) if (!rbl__jsonHex(j->text[j->pos + k])) { rbl__atlasError(j->s, "JSON: bad \\u escape%s", NULL, j->pos); return -1; }
                j->pos += 6; continue;
            }
            if (strchr("\"\\/bfnrt", e) == NULL || (e == 0)) { rbl__atlasError(j->s, "JSON: bad escape%s", NULL, j->pos); return -1; }
            j->pos += 2; continue;
        }
        j->pos++;
    }
    rbl__atlasError(j->s, "JSON: unterminated string%s", NULL, start - 1);
    return -1;
}

static int rbl__jsonNumber(rbl__Json *j)
{
    int start = j->pos, p = j->pos;
    const char *t = j->text;
    if ((p < j->size) && (t[p] == '-')) p++;
    if ((p < j->size) && (t[p] == '0')) p++;
    else if ((p < j->size) && (t[p] >= '1') && (t[p] <= '9')) { while ((p < j->size) && (t[p] >= '0') && (t[p] <= '9')) p++; }
    else { rbl__atlasError(j->s, "JSON: bad number%s", NULL, start); return -1; }
    if ((p < j->size) && (t[p] == '.'))
    {
        p++;
        if (!((p < j->size) && (t[p] >= '0') && (t[p] <= '9'))) { rbl__atlasError(j->s, "JSON: bad number%s", NULL, start); return -1; }
        while ((p < j->size) && (t[p] >= '0') && (t[p] <= '9')) p++;
    }
    if ((p < j->size) && ((t[p] == 'e') || (t[p] == 'E')))
    {
        p++;
        if ((p < j->size) && ((t[p] == '+') || (t[p] == '-'))) p++;
        if (!((p < j->size) && (t[p] >= '0') && (t[p] <= '9'))) { rbl__atlasError(j->s, "JSON: bad number%s", NULL, start); return -1; }
        while ((p < j->size) && (t[p] >= '0') && (t[p] <= '9')) p++;
    }
    int n = rbl__jsonNode(j, RBL__J_NUMBER, start);
    if (n < 0) return -1;
    j->nodes[n].len = p - start;
    j->pos = p;
    return n;
}

// Object or array; members are parsed recursively (depth bounded)
static int rbl__jsonContainer(rbl__Json *j, int depth)
{
    bool object = (j->text[j->pos] == '{');
    char close = object? '}' : ']';
    int n = rbl__jsonNode(j, object? RBL__J_OBJECT : RBL__J_ARRAY, j->pos);
    if (n < 0) return -1;
    j->pos++;
    rbl__jsonSkip(j);
    int count = 0;
    if ((j->pos < j->size) && (j->text[j->pos] == close)) j->pos++;
    else for (;;)
    {
        rbl__jsonSkip(j);
        if (object)
        {
            if ((j->pos >= j->size) || (j->text[j->pos] != '"')) { rbl__atlasError(j->s, "JSON: expected a member name%s", NULL, j->pos); return -1; }
            if (rbl__jsonString(j) < 0) return -1;
            rbl__jsonSkip(j);
            if ((j->pos >= j->size) || (j->text[j->pos] != ':')) { rbl__atlasError(j->s, "JSON: expected ':'%s", NULL, j->pos); return -1; }
            j->pos++;
            count++;
        }
        if (rbl__jsonValue(j, depth + 1) < 0) return -1;
        count++;
        rbl__jsonSkip(j);
        if (j->pos >= j->size) { rbl__atlasError(j->s, "JSON: truncated%s", NULL, j->pos); return -1; }
        if (j->text[j->pos] == ',') { j->pos++; continue; }
        if (j->text[j->pos] == close) { j->pos++; break; }
        rbl__atlasError(j->s, "JSON: expected ',' or a closing bracket%s", NULL, j->pos);
        return -1;
    }
    j->nodes[n].count = count;
    j->nodes[n].next = j->count;
    return n;
}

static int rbl__jsonValue(rbl__Json *j, int depth)
{
    if (depth > RBL__ATLAS_MAX_DEPTH) { rbl__atlasError(j->s, "JSON: nested deeper than 64%s", NULL, j->pos); return -1; }
    rbl__jsonSkip(j);
    if (j->pos >= j->size) { rbl__atlasError(j->s, "JSON: truncated%s", NULL, j->pos); return -1; }
    char c = j->text[j->pos];
    if ((c == '{') || (c == '[')) return rbl__jsonContainer(j, depth);
    if (c == '"') return rbl__jsonString(j);
    if ((c == '-') || ((c >= '0') && (c <= '9'))) return rbl__jsonNumber(j);
    static const char *words[3] = { "true", "false", "null" };
    static const int types[3] = { RBL__J_TRUE, RBL__J_FALSE, RBL__J_NULL };
    for (int k = 0; k < 3; k++)
    {
        int len = (int)strlen(words[k]);
        if ((j->size - j->pos >= len) && (memcmp(j->text + j->pos, words[k], (size_t)len) == 0))
        {
            int n = rbl__jsonNode(j, types[k], j->pos);
            if (n >= 0) { j->nodes[n].len = len; j->pos += len; }
            return n;
        }
    }
    rbl__atlasError(j->s, "JSON: unexpected character%s", NULL, j->pos);
    return -1;
}

// Member of an object by name (raw comparison; the last of duplicate keys wins, as JSON.parse)
static int rbl__jsonGet(const rbl__Json *j, int object, const char *key)
{
    if ((object < 0) || (j->nodes[object].type != RBL__J_OBJECT)) return -1;
    int found = -1, len = (int)strlen(key);
    for (int k = object + 1, i = 0; i < j->nodes[object].count; i += 2)
    {
        const rbl__JNode *name = &j->nodes[k];
        int value = name->next;
        if ((name->len == len) && (memcmp(j->text + name->start, key, (size_t)len) == 0)) found = value;
        k = j->nodes[value].next;
    }
    return found;
}

// UTF-8 of one code point (at most 4 bytes)
static int rbl__utf8(unsigned int cp, char *out)
{
    if (cp < 0x80) { out[0] = (char)cp; return 1; }
    if (cp < 0x800) { out[0] = (char)(0xC0 | (cp >> 6)); out[1] = (char)(0x80 | (cp & 0x3F)); return 2; }
    if (cp < 0x10000) { out[0] = (char)(0xE0 | (cp >> 12)); out[1] = (char)(0x80 | ((cp >> 6) & 0x3F)); out[2] = (char)(0x80 | (cp & 0x3F)); return 3; }
    out[0] = (char)(0xF0 | (cp >> 18)); out[1] = (char)(0x80 | ((cp >> 12) & 0x3F)); out[2] = (char)(0x80 | ((cp >> 6) & 0x3F)); out[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}

static unsigned int rbl__hex4(const char *p)
{
    unsigned int v = 0;
    for (int k = 0; k < 4; k++) { char c = p[k]; v = v*16u + (unsigned int)((c <= '9')? c - '0' : ((c | 32) - 'a' + 10)); }
    return v;
}

// Decoded copy of a string node in the name storage (escapes validated by the tokenizer; \u0000 and
// lone surrogates become U+FFFD so that names stay C strings). The decoded text never outgrows the raw.
static const char *rbl__jsonText(rbl__Json *j, int node)
{
    if ((node < 0) || (j->nodes[node].type != RBL__J_STRING)) return NULL;
    const char *p = j->text + j->nodes[node].start, *end = p + j->nodes[node].len;
    char *out = rbl__atlasPoolTake(j->s, (size_t)j->nodes[node].len + 1), *o = out;
    if (out == NULL) return NULL;
    while (p < end)
    {
        if (*p != '\\') { *o++ = *p++; continue; }
        char e = p[1];
        if (e != 'u')
        {
            static const char from[] = "\"\\/bfnrt", to[] = "\"\\/\b\f\n\r\t";
            *o++ = to[strchr(from, e) - from];
            p += 2; continue;
        }
        unsigned int cp = rbl__hex4(p + 2);
        p += 6;
        if ((cp >= 0xD800) && (cp < 0xDC00) && (end - p >= 6) && (p[0] == '\\') && (p[1] == 'u'))
        {
            unsigned int lo = rbl__hex4(p + 2);
            if ((lo >= 0xDC00) && (lo < 0xE000)) { cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00); p += 6; }
        }
        if ((cp == 0) || ((cp >= 0xD800) && (cp < 0xE000))) cp = 0xFFFD;   // 3 bytes, from 6 raw
        o += rbl__utf8(cp, o);                                              // 12 raw bytes give at most 4
    }
    *o = 0;
    return out;
}

static bool rbl__jsonIsText(const rbl__Json *j, int node, const char *word)
{
    int len = (int)strlen(word);
    return (node >= 0) && (j->nodes[node].type == RBL__J_STRING) && (j->nodes[node].len == len) && (memcmp(j->text + j->nodes[node].start, word, (size_t)len) == 0);
}

// A finite number from a number node, or a string holding exactly a JSON number ("repeat": "2")
static bool rbl__jsonNum(const rbl__Json *j, int node, double *out)
{
    if (node < 0) return false;
    const rbl__JNode *n = &j->nodes[node];
    if ((n->type != RBL__J_NUMBER) && (n->type != RBL__J_STRING)) return false;
    if ((n->len <= 0) || (n->len > 63)) return false;
    char buf[64];
    memcpy(buf, j->text + n->start, (size_t)n->len); buf[n->len] = 0;
    if (n->type == RBL__J_STRING)
    {
        // the same grammar as the tokenizer's numbers
        if (!((buf[0] == '-') || ((buf[0] >= '0') && (buf[0] <= '9')))) return false;
        for (const char *q = buf; *q; q++) if (strchr("0123456789+-.eE", *q) == NULL) return false;
    }
    char *end = NULL;
    double v = strtod(buf, &end);
    if ((end != buf + n->len) || !isfinite(v)) return false;
    *out = v;
    return true;
}

// Number member, with a range; missing: def (when optional) else false
// Members of an object found in one pass, the last of duplicate keys winning (as rbl__jsonGet):
// out[k] = the value of keys[k], -1 when absent
static void rbl__jsonPick(const rbl__Json *j, int object, const char *const *keys, int n, int *out)
{
    for (int k = 0; k < n; k++) out[k] = -1;
    if ((object < 0) || (j->nodes[object].type != RBL__J_OBJECT)) return;
    for (int c = object + 1, i = 0; i < j->nodes[object].count; i += 2)
    {
        const rbl__JNode *name = &j->nodes[c];
        const char *t = j->text + name->start;
        for (int k = 0; k < n; k++)      // strncmp stops at the key's end; then the lengths must agree
            if ((name->len > 0) && (keys[k][0] == t[0]) && (strncmp(keys[k], t, (size_t)name->len) == 0) && (keys[k][name->len] == 0)) out[k] = name->next;
        c = j->nodes[name->next].next;
    }
}

// Number value v (the member key of owner), with a range; absent (v < 0): def when optional, else false
static bool rbl__jsonNumberAt(rbl__Json *j, int v, int owner, const char *key, double lo, double hi, bool optional, double def, double *out)
{
    if (v < 0) { if (optional) { *out = def; return true; } rbl__atlasError(j->s, "missing \"%s\"", key, j->nodes[owner].start); return false; }
    double x;
    if (!rbl__jsonNum(j, v, &x) || (x < lo) || (x > hi)) { rbl__atlasErrorf(j->s, j->nodes[v].start, "\"%s\" is not a number in %g..%g", key, lo, hi); return false; }
    *out = x;
    return true;
}

static bool rbl__jsonMember(rbl__Json *j, int object, const char *key, double lo, double hi, bool optional, double def, double *out)
{
    int v = rbl__jsonGet(j, object, key);
    if (v < 0) { if (optional) { *out = def; return true; } rbl__atlasError(j->s, "missing \"%s\"", key, j->nodes[object].start); return false; }
    double x;
    if (!rbl__jsonNum(j, v, &x) || (x < lo) || (x > hi)) { rbl__atlasErrorf(j->s, j->nodes[v].start, "\"%s\" is not a number in %g..%g", key, lo, hi); return false; }
    *out = x;
    return true;
}

static bool rbl__jsonBoolAt(rbl__Json *j, int v, const char *key, bool *out)
{
    *out = false;
    if (v < 0) return true;
    if (j->nodes[v].type == RBL__J_TRUE) { *out = true; return true; }
    if (j->nodes[v].type == RBL__J_FALSE) return true;
    rbl__atlasError(j->s, "\"%s\" is not true or false", key, j->nodes[v].start);
    return false;
}

// {x, y, w, h} (any subset named in names, in order, at most 4) of value r (the member key of owner) into out[]
static bool rbl__jsonRectAt(rbl__Json *j, int r, int owner, const char *key, const char *const *names, int n, bool optional, double *out)
{
    if (r < 0) { if (optional) return true; rbl__atlasError(j->s, "missing \"%s\"", key, j->nodes[owner].start); return false; }
    if (j->nodes[r].type != RBL__J_OBJECT) { rbl__atlasError(j->s, "\"%s\" is not an object", key, j->nodes[r].start); return false; }
    int at[4];
    rbl__jsonPick(j, r, names, n, at);
    for (int k = 0; k < n; k++)
        if (!rbl__jsonNumberAt(j, at[k], r, names[k], -RBL__ATLAS_MAX_COORD, RBL__ATLAS_MAX_COORD, false, 0.0, &out[k])) return false;
    return true;
}

static bool rbl__jsonRect(rbl__Json *j, int object, const char *key, const char *const *names, int n, bool optional, double *out)
{
    return rbl__jsonRectAt(j, rbl__jsonGet(j, object, key), object, key, names, n, optional, out);
}

static RblAtlasPage *rbl__atlasAddPage(rbl__AtlasState *s, const char *image, int width, int height)
{
    if (s->pageCount >= RBL__ATLAS_MAX_PAGES) { rbl__atlasErrorf(s, -1, "more than %d sheets", RBL__ATLAS_MAX_PAGES); return NULL; }
    RBL__ATLAS_GROW(s, s->pages, s->pageCount, s->pageCap, RblAtlasPage, "sheets", return NULL);
    RblAtlasPage *p = &s->pages[s->pageCount++];
    memset(p, 0, sizeof(*p));
    p->image = image; p->width = width; p->height = height; p->scale = 1.0f;
    return p;
}

// ---- sheet files (RblLoadAtlas) -----------------------------------------------------------------
// A copy in a block of its own (the text's name block keeps its room for the names)
static const char *rbl__atlasKeep(rbl__AtlasState *s, const char *text)
{
    RBL__ATLAS_GROW(s, s->pools, s->poolCount, s->poolCap, char *, "name blocks", return NULL);
    size_t n = strlen(text);
    char *p = (char *)RBL_MALLOC(n + 1);
    if (p == NULL) { rbl__atlasErrorf(s, -1, "out of memory"); return NULL; }
    memcpy(p, text, n + 1);
    s->pools[s->poolCount++] = p;
    return p;
}

// File name part of a path (either separator: exporters on Windows write backslashes)
static const char *rbl__pathBase(const char *path)
{
    const char *b = path;
    for (const char *c = path; *c != 0; c++) if ((*c == '/') || (*c == '\\')) b = c + 1;
    return b;
}

// Length of a file name without its extension (a leading dot belongs to the name)
static size_t rbl__pathStem(const char *base)
{
    const char *dot = strrchr(base, '.');
    return ((dot != NULL) && (dot != base))? (size_t)(dot - base) : strlen(base);
}

static bool rbl__pathAbsolute(const char *p)
{
    bool drive = ((p[0] | 32) >= 'a') && ((p[0] | 32) <= 'z') && (p[1] == ':') && ((p[2] == '/') || (p[2] == '\\'));
    return (p[0] == '/') || (p[0] == '\\') || drive;
}

// <stem><suffix><extension> of a sheet path (its normal sheet by a naming convention); false if too long
static bool rbl__pathWithSuffix(const char *image, const char *suffix, char *out, size_t size)
{
    const char *base = rbl__pathBase(image);
    size_t stem = (size_t)(base - image) + rbl__pathStem(base);
    int n = snprintf(out, size, "%.*s%s%s", (int)stem, image, suffix, image + stem);
    return (n >= 0) && ((size_t)n < size);
}

// The file a sheet name finds, kept; NULL with one error naming every path tried. Tried in order:
// the path as written (joined to the atlas file's folder unless absolute), its base name beside
// the atlas file, then the base name of `stemOf` (the atlas file, or the colour sheet for its
// normal sheet) + suffix + the written extension (".png" when none).
static const char *rbl__atlasFindFile(rbl__AtlasState *s, const char *file, const char *written, const char *stemOf, const char *suffix, const char *what)
{
    char tried[3][RBL__ATLAS_PATH];
    int n = 0;
    int dl = (int)(rbl__pathBase(file) - file);    // the folder with its separator ("" = current)
    const char *base = rbl__pathBase(written), *stemBase = rbl__pathBase(stemOf);
    const char *ext = strrchr(base, '.');
    if ((ext == NULL) || (ext == base)) ext = ".png";
    for (int k = 0; k < 3; k++)
    {
        char *c = tried[n];
        int len = 0;
        if ((k < 2) && (written[0] == 0)) continue;
        if (k == 0) len = rbl__pathAbsolute(written)? snprintf(c, RBL__ATLAS_PATH, "%s", written) : snprintf(c, RBL__ATLAS_PATH, "%.*s%s", dl, file, written);
        else if (k == 1) len = snprintf(c, RBL__ATLAS_PATH, "%.*s%s", dl, file, base);
        else len = snprintf(c, RBL__ATLAS_PATH, "%.*s%.*s%s%s", dl, file, (int)rbl__pathStem(stemBase), stemBase, suffix, ext);
        if ((len < 0) || (len >= RBL__ATLAS_PATH)) { rbl__atlasErrorf(s, -1, "%s path longer than %d bytes", what, RBL__ATLAS_PATH - 1); return NULL; }
        bool again = false;
        for (int i = 0; i < n; i++) again = again || (strcmp(tried[i], c) == 0);
        if (again) continue;
        if (FileExists(c)) return rbl__atlasKeep(s, c);
        n++;
    }
    rbl__atlasErrorf(s, -1, "%s \"%s\" not found: tried \"%s\"%s%s%s%s%s%s", what, written, tried[0], (n > 1)? ", \"" : "", (n > 1)? tried[1] : "", (n > 1)? "\"" : "",
                     (n > 2)? ", \"" : "", (n > 2)? tried[2] : "", (n > 2)? "\"" : "");
    return NULL;
}

// The same-layout normal sheet by the "_n" convention (TexturePacker, SpriteIlluminator, Paper2D), or NULL
static bool rbl__atlasProbeNormal(rbl__AtlasState *s, RblAtlasPage *page)
{
    char path[RBL__ATLAS_PATH];
    if (!rbl__pathWithSuffix(page->image, "_n", path, sizeof(path)) || !FileExists(path)) return true;
    page->normalImage = rbl__atlasKeep(s, path);
    return page->normalImage != NULL;
}

// Fills the derived fields of a frame from its upright rectangle and trim; false (logged) when
// inconsistent. swap: stored in an h x w block (a quarter turn); mirror: both extents negated (a
// half turn more: libGDX's counter-clockwise quarter, or its half turn).
static bool rbl__atlasFinishFrame(rbl__AtlasState *s, RblAtlasFrame *f, bool swap, bool mirror, const RblAtlasPage *page)
{
    float x = f->block.x, y = f->block.y, w = f->block.width, h = f->block.height;   // upright size on entry
    if (!(w > 0.0f) || !(h > 0.0f) || (x < 0.0f) || (y < 0.0f)) { rbl__atlasError(s, "frame \"%s\": empty or negative rectangle", f->name, -1); return false; }
    if (swap) { f->block.width = h; f->block.height = w; }
    if ((page->width > 0) && (page->height > 0) && ((f->block.x + f->block.width > (float)page->width) || (f->block.y + f->block.height > (float)page->height)))
    { rbl__atlasError(s, "frame \"%s\": outside its sheet", f->name, -1); return false; }
    f->source = f->block;
    f->flags = swap? (unsigned int)RBL_FRAME_ROTATED : 0u;
    if (mirror) { f->source.width = -f->source.width; f->source.height = -f->source.height; }
    if (!(f->size.x > 0.0f) || !(f->size.y > 0.0f) || (f->trim.x < 0.0f) || (f->trim.y < 0.0f) ||
        (f->trim.x + f->trim.width > f->size.x) || (f->trim.y + f->trim.height > f->size.y))
    { rbl__atlasError(s, "frame \"%s\": trimmed rectangle outside the untrimmed size", f->name, -1); return false; }
    if (!isfinite(f->pivot.x) || !isfinite(f->pivot.y) || (fabsf(f->pivot.x) > 1e6f) || (fabsf(f->pivot.y) > 1e6f))
    { rbl__atlasError(s, "frame \"%s\": pivot out of range", f->name, -1); return false; }
    const Rectangle c = f->center;
    if ((c.x < 0.0f) || (c.y < 0.0f) || (c.width < 0.0f) || (c.height < 0.0f) || (c.x + c.width > f->size.x) || (c.y + c.height > f->size.y))
    { rbl__atlasError(s, "frame \"%s\": 9-slice centre outside the frame", f->name, -1); return false; }
    return true;
}

static const char *const rbl__xywh[4] = { "x", "y", "w", "h" };

// Polygon points, [[x, y], ...] or [x, y, x, y, ...], each inside box, appended to the point table;
// *count: in, the number required (-1 = any 3..65535); out, the number read
static bool rbl__atlasJsonPoints(rbl__Json *j, int node, const char *key, const char *frame, Rectangle box, int *count)
{
    rbl__AtlasState *s = j->s;
    if ((j->nodes[node].type != RBL__J_ARRAY) || (j->nodes[node].count == 0)) { rbl__atlasErrorf(s, j->nodes[node].start, "frame \"%s\": \"%s\" is not an array of points", frame, key); return false; }
    bool pairs = (j->nodes[node + 1].type == RBL__J_ARRAY);
    int n = pairs? j->nodes[node].count : j->nodes[node].count/2;
    if ((!pairs && (j->nodes[node].count%2 != 0)) || (n < 3) || (n > RBL__ATLAS_MAX_POLYGON) || ((*count >= 0) && (n != *count)))
    { rbl__atlasErrorf(s, j->nodes[node].start, "frame \"%s\": \"%s\" holds %d points (3..%d, as many as \"vertices\")", frame, key, n, RBL__ATLAS_MAX_POLYGON); return false; }
    RBL__ATLAS_GROWN(s, s->polyPoints, s->polyPointCount, n, s->polyPointCap, Vector2, "polygon points", return false);
    Vector2 *out = s->polyPoints + s->polyPointCount;
    for (int i = 0, c = node + 1; i < n; i++)
    {
        int xn = c, yn;
        if (pairs)
        {
            if ((j->nodes[c].type != RBL__J_ARRAY) || (j->nodes[c].count != 2)) { rbl__atlasErrorf(s, j->nodes[c].start, "frame \"%s\": \"%s\" point %d is not [x, y]", frame, key, i); return false; }
            xn = c + 1; yn = j->nodes[xn].next; c = j->nodes[c].next;
        }
        else { yn = j->nodes[c].next; c = j->nodes[yn].next; }
        double x, y;
        if (!rbl__jsonNum(j, xn, &x) || !rbl__jsonNum(j, yn, &y) || (x < box.x) || (y < box.y) || (x > (double)box.x + box.width) || (y > (double)box.y + box.height))
        { rbl__atlasErrorf(s, j->nodes[xn].start, "frame \"%s\": \"%s\" point %d not a number pair inside %g,%g %gx%g", frame, key, i, box.x, box.y, box.width, box.height); return false; }
        out[i] = rbl__v2((float)x, (float)y);
    }
    s->polyPointCount += n;
    *count = n;
    return true;
}

// Triangle corners, [[a, b, c], ...] or [a, b, c, ...], each a vertex index, appended to the index table
static bool rbl__atlasJsonTriangles(rbl__Json *j, int node, const char *frame, int vertexCount, int *count)
{
    rbl__AtlasState *s = j->s;
    if ((j->nodes[node].type != RBL__J_ARRAY) || (j->nodes[node].count == 0)) { rbl__atlasErrorf(s, j->nodes[node].start, "frame \"%s\": \"triangles\" is not an array", frame); return false; }
    bool nested = (j->nodes[node + 1].type == RBL__J_ARRAY);
    int n = nested? j->nodes[node].count : j->nodes[node].count/3;
    if (!nested && (j->nodes[node].count%3 != 0)) { rbl__atlasErrorf(s, j->nodes[node].start, "frame \"%s\": \"triangles\" holds %d indices, not a multiple of 3", frame, j->nodes[node].count); return false; }
    if (n > RBL_MAX_ATLAS_ENTRIES/3) { rbl__atlasErrorf(s, -1, "more than %d polygon indices (RBL_MAX_ATLAS_ENTRIES)", RBL_MAX_ATLAS_ENTRIES); return false; }
    RBL__ATLAS_GROWN(s, s->polyIndices, s->polyIndexCount, 3*n, s->polyIndexCap, unsigned short, "polygon indices", return false);
    unsigned short *out = s->polyIndices + s->polyIndexCount;
    for (int t = 0, c = node + 1; t < n; t++)
    {
        int corner = c;
        if (nested)
        {
            if ((j->nodes[c].type != RBL__J_ARRAY) || (j->nodes[c].count != 3)) { rbl__atlasErrorf(s, j->nodes[c].start, "frame \"%s\": triangle %d is not [a, b, c]", frame, t); return false; }
            corner = c + 1;
            c = j->nodes[c].next;
        }
        for (int k = 0; k < 3; k++)
        {
            double v;
            if (!rbl__jsonNum(j, corner, &v) || (v < 0.0) || (v >= vertexCount) || (v != floor(v)))
            { rbl__atlasErrorf(s, j->nodes[corner].start, "frame \"%s\": triangle %d corner %d is not a vertex index 0..%d", frame, t, k, vertexCount - 1); return false; }
            out[3*t + k] = (unsigned short)v;
            corner = j->nodes[corner].next;
        }
        if (!nested) c = corner;
    }
    s->polyIndexCount += 3*n;
    *count = 3*n;
    return true;
}

// A polygon frame (TexturePacker's polygon packing): vertices in the untrimmed frame, their sheet
// texels inside the frame's block, triangles over them; the rows are published with the atlas
static bool rbl__atlasJsonPolygon(rbl__Json *j, int obj, int v, int uv, int tri, const RblAtlasFrame *f)
{
    rbl__AtlasState *s = j->s;
    if ((v < 0) && (uv < 0) && (tri < 0)) return true;
    if ((v < 0) || (uv < 0) || (tri < 0)) { rbl__atlasErrorf(s, j->nodes[obj].start, "frame \"%s\": a polygon needs \"vertices\", \"verticesUV\" and \"triangles\"", f->name); return false; }
    RBL__ATLAS_GROW(s, s->polygons, s->polygonCount, s->polygonCap, RblAtlasPolygon, "polygons", return false);
    RBL__ATLAS_GROW(s, s->polygonRefs, s->polygonCount, s->polygonRefCap, rbl__AtlasPolyRef, "polygons", return false);
    rbl__AtlasPolyRef ref = { s->frameCount, s->polyPointCount, s->polyIndexCount };
    int n = -1, indices = 0;
    if (!rbl__atlasJsonPoints(j, v, "vertices", f->name, rbl__rect(0.0f, 0.0f, f->size.x, f->size.y), &n) ||
        !rbl__atlasJsonPoints(j, uv, "verticesUV", f->name, f->block, &n) || !rbl__atlasJsonTriangles(j, tri, f->name, n, &indices)) return false;
    RblAtlasPolygon *p = &s->polygons[s->polygonCount];
    memset(p, 0, sizeof(*p));
    p->vertexCount = n; p->indexCount = indices;
    s->polygonRefs[s->polygonCount++] = ref;
    return true;
}

// One TexturePacker / Aseprite frame object: its members in one pass
#define RBL__FRAME_KEYS 11
static const char *const rbl__frameKeys[RBL__FRAME_KEYS] = { "frame", "rotated", "spriteSourceSize", "sourceSize", "anchor", "pivot", "duration",
                                                              "scale9Borders", "vertices", "verticesUV", "triangles" };
static bool rbl__atlasJsonFrame(rbl__Json *j, int obj, const char *name, int page)
{
    rbl__AtlasState *s = j->s;
    if ((obj < 0) || (j->nodes[obj].type != RBL__J_OBJECT)) { rbl__atlasError(s, "frame \"%s\" is not an object", name, -1); return false; }
    double fr[4], sss[4], src[2], piv[2] = { 0.5, 1.0 }, dur = 0.0, nine[4] = { 0.0, 0.0, 0.0, 0.0 };
    bool rotated = false;
    int m[RBL__FRAME_KEYS];
    rbl__jsonPick(j, obj, rbl__frameKeys, RBL__FRAME_KEYS, m);
    if (!rbl__jsonRectAt(j, m[0], obj, "frame", rbl__xywh, 4, false, fr) || !rbl__jsonBoolAt(j, m[1], "rotated", &rotated)) return false;
    sss[0] = 0.0; sss[1] = 0.0; sss[2] = fr[2]; sss[3] = fr[3];
    src[0] = fr[2]; src[1] = fr[3];
    if (!rbl__jsonRectAt(j, m[2], obj, "spriteSourceSize", rbl__xywh, 4, true, sss)) return false;
    if (!rbl__jsonRectAt(j, m[3], obj, "sourceSize", rbl__xywh + 2, 2, true, src)) return false;
    const char *const xy[2] = { "x", "y" };
    // pivot (TexturePacker), anchor (the Pixi exporter's name for it); none: the bottom centre
    if (!rbl__jsonRectAt(j, m[4], obj, "anchor", xy, 2, true, piv) || !rbl__jsonRectAt(j, m[5], obj, "pivot", xy, 2, true, piv)) return false;
    if (!rbl__jsonNumberAt(j, m[6], obj, "duration", 0.0, 1e9, true, 0.0, &dur)) return false;
    if (!rbl__jsonRectAt(j, m[7], obj, "scale9Borders", rbl__xywh, 4, true, nine)) return false;     // Phaser 3's 9-slice centre
    RBL__ATLAS_GROW(s, s->frames, s->frameCount, s->frameCap, RblAtlasFrame, "frames", return false);
    RblAtlasFrame *f = &s->frames[s->frameCount];
    memset(f, 0, sizeof(*f));
    f->name = name; f->page = page; f->index = -1;
    f->block = rbl__rect((float)fr[0], (float)fr[1], (float)fr[2], (float)fr[3]);
    // the drawn part is the frame's rectangle, placed at the trim offset (sss w/h repeat the frame's)
    f->trim = rbl__rect((float)sss[0], (float)sss[1], (float)fr[2], (float)fr[3]);
    f->size = rbl__v2((float)src[0], (float)src[1]);
    f->pivot = rbl__v2((float)piv[0], (float)piv[1]);
    f->duration = (float)(dur/1000.0);
    f->center = rbl__rect((float)nine[0], (float)nine[1], (float)nine[2], (float)nine[3]);
    if (!rbl__atlasFinishFrame(s, f, rotated, false, &s->pages[page]) || !rbl__atlasJsonPolygon(j, obj, m[8], m[9], m[10], f)) return false;
    s->frameCount++;
    return true;
}

// Frames of one sheet: an object (hash form, names as keys) or an array (each with "filename")
static bool rbl__atlasJsonFrames(rbl__Json *j, int frames, int page)
{
    bool hash = (j->nodes[frames].type == RBL__J_OBJECT);
    for (int k = frames + 1, i = 0; i < j->nodes[frames].count; i += hash? 2 : 1)
    {
        int value = hash? j->nodes[k].next : k;
        const char *name = hash? rbl__jsonText(j, k) : rbl__jsonText(j, rbl__jsonGet(j, value, "filename"));
        if (name == NULL) { rbl__atlasError(j->s, "a frame has no name (\"filename\")%s", NULL, j->nodes[value].start); return false; }
        if (!rbl__atlasJsonFrame(j, value, name, page)) return false;
        k = j->nodes[value].next;
    }
    return true;
}

// Whether a frame name belongs to a tag: the tag's name followed by the end or a separator
static bool rbl__atlasNameInTag(const char *frame, const char *tag)
{
    size_t n = strlen(tag);
    if ((n == 0) || (strncmp(frame, tag, n) != 0)) return false;
    char c = frame[n];
    return (c == 0) || (c == ':') || (c == ' ') || (c == '.') || (c == '#') || (c == '-');
}

// Aseprite tag frame range. from/to count the sheet's frames, except in an export of several
// sprites, where they count each sprite's own frames: then the frames named after the tag
// (default "{tag}:{frame}" names) locate it. Sheet indices are kept when they fit the names, or
// when no frame is named after the tag.
static bool rbl__asepriteTagRange(const rbl__AtlasState *s, int first, const char *tag, int from, int to, int *outFrom)
{
    int n = s->frameCount - first, len = to - from + 1;
    bool global = (from >= 0) && (to < n);
    if (global)
    {
        bool named = true;
        for (int i = from; (i <= to) && named; i++) named = rbl__atlasNameInTag(s->frames[first + i].name, tag);
        if (named) { *outFrom = first + from; return true; }
    }
    for (int i = 0; i + len <= n; i++)
    {
        bool run = true;
        for (int k = 0; (k < len) && run; k++) run = rbl__atlasNameInTag(s->frames[first + i + k].name, tag);
        if (run) { *outFrom = first + i; return true; }
    }
    if (global) { *outFrom = first + from; return true; }
    return false;
}

static bool rbl__atlasJsonTags(rbl__Json *j, int meta, int first)
{
    rbl__AtlasState *s = j->s;
    int tags = rbl__jsonGet(j, meta, "frameTags");
    if (tags < 0) return true;
    if (j->nodes[tags].type != RBL__J_ARRAY) { rbl__atlasError(s, "meta.frameTags is not an array%s", NULL, j->nodes[tags].start); return false; }
    for (int t = tags + 1, i = 0; i < j->nodes[tags].count; i++, t = j->nodes[t].next)
    {
        if (j->nodes[t].type != RBL__J_OBJECT) { rbl__atlasError(s, "a frame tag is not an object%s", NULL, j->nodes[t].start); return false; }
        const char *name = rbl__jsonText(j, rbl__jsonGet(j, t, "name"));
        if (name == NULL) { rbl__atlasError(s, "a frame tag has no name%s", NULL, j->nodes[t].start); return false; }
        double from, to, repeat;
        if (!rbl__jsonMember(j, t, "from", 0.0, 1e9, false, 0.0, &from) || !rbl__jsonMember(j, t, "to", 0.0, 1e9, false, 0.0, &to) ||
            !rbl__jsonMember(j, t, "repeat", 0.0, RBL__ATLAS_MAX_REPEAT, true, 0.0, &repeat)) return false;
        if ((from > to) || (from != floor(from)) || (to != floor(to)) || (repeat != floor(repeat))) { rbl__atlasError(s, "tag \"%s\": from/to/repeat not whole or from > to", name, j->nodes[t].start); return false; }
        int dir = RBL_SPRITE_FORWARD, d = rbl__jsonGet(j, t, "direction");
        if (d >= 0)
        {
            if (rbl__jsonIsText(j, d, "forward")) dir = RBL_SPRITE_FORWARD;
            else if (rbl__jsonIsText(j, d, "reverse")) dir = RBL_SPRITE_REVERSE;
            else if (rbl__jsonIsText(j, d, "pingpong")) dir = RBL_SPRITE_PINGPONG;
            else if (rbl__jsonIsText(j, d, "pingpong_reverse")) dir = RBL_SPRITE_PINGPONG_REVERSE;
            else { rbl__atlasError(s, "tag \"%s\": unknown direction", name, j->nodes[d].start); return false; }
        }
        int start;
        if (!rbl__asepriteTagRange(s, first, name, (int)from, (int)to, &start)) { rbl__atlasError(s, "tag \"%s\": frames outside the sheet", name, j->nodes[t].start); return false; }
        RBL__ATLAS_GROW(s, s->tags, s->tagCount, s->tagCap, RblAtlasTag, "tags", return false);
        RblAtlasTag *g = &s->tags[s->tagCount++];
        g->name = name; g->from = start; g->to = start + (int)(to - from); g->direction = dir; g->repeat = (int)repeat;
    }
    return true;
}

// Aseprite slices: one entry per key, each a sub-frame with its own pivot (none given: its bottom
// centre) and 9-slice centre; a key applies until the slice's next key. When exactly one slice of
// the export has pivots, it is the pivot slice the one-slice workflow means: its pivots become the
// pivots of the frames its keys cover (canvas pixels -> fractions of the untrimmed size).
static bool rbl__atlasJsonSlices(rbl__Json *j, int meta, int first)
{
    rbl__AtlasState *s = j->s;
    int slices = rbl__jsonGet(j, meta, "slices");
    if (slices < 0) return true;
    if (j->nodes[slices].type != RBL__J_ARRAY) { rbl__atlasError(s, "meta.slices is not an array%s", NULL, j->nodes[slices].start); return false; }
    int pivoted = 0, pivotFrom = 0, pivotTo = 0;        // slices with pivots; the keys of the last one
    const char *const xy[2] = { "x", "y" };
    for (int e = slices + 1, i = 0; i < j->nodes[slices].count; i++, e = j->nodes[e].next)
    {
        const char *name = rbl__jsonText(j, rbl__jsonGet(j, e, "name"));
        int keys = rbl__jsonGet(j, e, "keys");
        if ((name == NULL) || (keys < 0) || (j->nodes[keys].type != RBL__J_ARRAY)) { rbl__atlasError(s, "a slice lacks a name or keys%s", NULL, j->nodes[e].start); return false; }
        int firstKey = s->sliceCount;
        bool anyPivot = false;
        for (int k = keys + 1, n = 0; n < j->nodes[keys].count; n++, k = j->nodes[k].next)
        {
            double fr, b[4], p[2] = { 0.0, 0.0 }, c[4] = { 0.0, 0.0, 0.0, 0.0 };
            if ((j->nodes[k].type != RBL__J_OBJECT) || !rbl__jsonMember(j, k, "frame", 0.0, 1e9, false, 0.0, &fr) || (fr != floor(fr)) ||
                !rbl__jsonRect(j, k, "bounds", rbl__xywh, 4, false, b) || !rbl__jsonRect(j, k, "pivot", xy, 2, true, p) || !rbl__jsonRect(j, k, "center", rbl__xywh, 4, true, c))
            { rbl__atlasError(s, "slice \"%s\": bad key", name, j->nodes[k].start); return false; }
            if (first + fr >= s->frameCount) { rbl__atlasErrorf(s, j->nodes[k].start, "slice \"%s\": key on frame %g, past the sheet's %d frames", name, fr, s->frameCount - first); return false; }
            if ((n > 0) && (fr <= s->slices[s->sliceCount - 1].frame - first)) { rbl__atlasError(s, "slice \"%s\": keys out of frame order", name, j->nodes[k].start); return false; }
            if (!(b[2] > 0.0) || !(b[3] > 0.0) || (c[0] < 0.0) || (c[1] < 0.0) || (c[2] < 0.0) || (c[3] < 0.0) || (c[0] + c[2] > b[2]) || (c[1] + c[3] > b[3]))
            { rbl__atlasError(s, "slice \"%s\": empty bounds, or a center outside them", name, j->nodes[k].start); return false; }
            if (n > 0) s->slices[s->sliceCount - 1].lastFrame = first + (int)fr - 1;
            RBL__ATLAS_GROW(s, s->slices, s->sliceCount, s->sliceCap, RblAtlasSlice, "slice keys", return false);
            RblAtlasSlice *sl = &s->slices[s->sliceCount++];
            memset(sl, 0, sizeof(*sl));
            sl->name = name; sl->frame = first + (int)fr; sl->lastFrame = s->frameCount - 1;
            sl->bounds = rbl__rect((float)b[0], (float)b[1], (float)b[2], (float)b[3]);
            sl->hasPivot = (rbl__jsonGet(j, k, "pivot") >= 0);
            sl->pivot = sl->hasPivot? rbl__v2((float)(b[0] + p[0]), (float)(b[1] + p[1])) : rbl__v2((float)(b[0] + 0.5*b[2]), (float)(b[1] + b[3]));
            if (c[2]*c[3] > 0.0) sl->center = rbl__rect((float)(b[0] + c[0]), (float)(b[1] + c[1]), (float)c[2], (float)c[3]);
            anyPivot = anyPivot || sl->hasPivot;
        }
        if (anyPivot) { pivoted++; pivotFrom = firstKey; pivotTo = s->sliceCount; }
    }
    if (pivoted != 1) return true;
    for (int k = pivotFrom; k < pivotTo; k++)
    {
        const RblAtlasSlice *key = &s->slices[k];
        if (!key->hasPivot) continue;
        for (int f = key->frame; f <= key->lastFrame; f++)
        {
            s->frames[f].pivot.x = key->pivot.x/s->frames[f].size.x;
            s->frames[f].pivot.y = key->pivot.y/s->frames[f].size.y;
        }
    }
    return true;
}

// One JSON sheet from obj (meta, or a textures[] entry): size (whole texels), scale (obj's, else
// meta's), image and normalMap. file: the text's path (RblLoadAtlas: the image is looked for, a
// "_n" sheet beside it found); NULL: from memory, names kept as written.
static bool rbl__atlasJsonPage(rbl__Json *j, int obj, int meta, const char *file, const char *where)
{
    rbl__AtlasState *s = j->s;
    double sz[2] = { 0.0, 0.0 }, scale = 1.0;
    if ((obj >= 0) && !rbl__jsonRect(j, obj, "size", rbl__xywh + 2, 2, true, sz)) return false;
    if ((obj >= 0) && (rbl__jsonGet(j, obj, "size") >= 0))
        for (int k = 0; k < 2; k++)
            if (!(sz[k] >= 1.0) || (sz[k] != floor(sz[k])))
            { rbl__atlasErrorf(s, j->nodes[rbl__jsonGet(j, obj, "size")].start, "%s.size %gx%g is not whole texels 1..%g", where, sz[0], sz[1], RBL__ATLAS_MAX_COORD); return false; }
    int sc = rbl__jsonGet(j, obj, "scale");
    if (sc < 0) sc = rbl__jsonGet(j, meta, "scale");
    if ((sc >= 0) && (!rbl__jsonNum(j, sc, &scale) || (scale < 1.0/RBL__ATLAS_MAX_SCALE) || (scale > RBL__ATLAS_MAX_SCALE)))
    { rbl__atlasErrorf(s, j->nodes[sc].start, "%s.scale is not a number in 1/%g..%g", where, RBL__ATLAS_MAX_SCALE, RBL__ATLAS_MAX_SCALE); return false; }
    int img = rbl__jsonGet(j, obj, "image"), nrm = rbl__jsonGet(j, obj, "normalMap");
    const char *image = "", *normal = NULL;
    if (img >= 0)
    {
        image = rbl__jsonText(j, img);
        if (image == NULL) { rbl__atlasErrorf(s, j->nodes[img].start, "%s.image is not a string", where); return false; }
    }
    if (nrm >= 0)
    {
        normal = rbl__jsonText(j, nrm);
        if (normal == NULL) { rbl__atlasErrorf(s, j->nodes[nrm].start, "%s.normalMap is not a string", where); return false; }
    }
    if (file != NULL)
    {
        image = rbl__atlasFindFile(s, file, image, file, "", "sheet");
        if ((image == NULL) || ((normal != NULL) && ((normal = rbl__atlasFindFile(s, file, normal, image, "_n", "normal sheet")) == NULL))) return false;
    }
    RblAtlasPage *page = rbl__atlasAddPage(s, image, (int)sz[0], (int)sz[1]);
    if (page == NULL) return false;
    page->scale = (float)scale;
    page->normalImage = normal;
    return (file == NULL) || (normal != NULL) || rbl__atlasProbeNormal(s, page);
}

// TexturePacker / Aseprite JSON: "frames" (hash or array) with meta.image, or TexturePacker's
// multi-texture (Phaser 3) "textures": one sheet per entry, its normalMap paired with it
static bool rbl__atlasParseJson(rbl__AtlasState *s, const char *text, int size, const char *file, int *format, rbl__Json *jOut)
{
    rbl__Json j0 = { text, size, 0, NULL, 0, 0, s };
    *jOut = j0;
    rbl__Json *j = jOut;
    if ((size >= 3) && ((unsigned char)text[0] == 0xEF) && ((unsigned char)text[1] == 0xBB) && ((unsigned char)text[2] == 0xBF)) j->pos = 3;
    int root = rbl__jsonValue(j, 0);
    if (root < 0) return false;
    rbl__jsonSkip(j);
    if (j->pos != j->size) { rbl__atlasError(s, "JSON: text after the document%s", NULL, j->pos); return false; }
    if (j->nodes[root].type != RBL__J_OBJECT) { rbl__atlasError(s, "JSON: the document is not an object%s", NULL, 0); return false; }
    int frames = rbl__jsonGet(j, root, "frames"), textures = rbl__jsonGet(j, root, "textures"), meta = rbl__jsonGet(j, root, "meta");
    if ((frames >= 0) && (textures >= 0)) { rbl__atlasError(s, "both \"frames\" and \"textures\" (one sheet or several? neither read)%s", NULL, 0); return false; }
    if ((textures >= 0) && ((j->nodes[textures].type != RBL__J_ARRAY) || (j->nodes[textures].count == 0))) { rbl__atlasError(s, "\"textures\" is not a non-empty array%s", NULL, j->nodes[textures].start); return false; }
    if ((textures < 0) && ((frames < 0) || ((j->nodes[frames].type != RBL__J_OBJECT) && (j->nodes[frames].type != RBL__J_ARRAY)))) { rbl__atlasError(s, "no \"frames\" object or array, nor a \"textures\" array%s", NULL, 0); return false; }
    if ((meta >= 0) && (j->nodes[meta].type != RBL__J_OBJECT)) { rbl__atlasError(s, "\"meta\" is not an object%s", NULL, j->nodes[meta].start); return false; }
    if (*format == RBL_ATLAS_AUTO)
    {
        int app = rbl__jsonGet(j, meta, "app");
        bool aseprite = false;
        if ((app >= 0) && (j->nodes[app].type == RBL__J_STRING))
            for (int k = 0; k + 8 <= j->nodes[app].len; k++) if (memcmp(j->text + j->nodes[app].start + k, "aseprite", 8) == 0) aseprite = true;
        *format = (aseprite || (rbl__jsonGet(j, meta, "frameTags") >= 0))? RBL_ATLAS_ASEPRITE : RBL_ATLAS_TEXTUREPACKER;
    }
    int first = s->frameCount;
    if (textures >= 0)
    {
        for (int t = textures + 1, i = 0; i < j->nodes[textures].count; i++, t = j->nodes[t].next)
        {
            char where[32];
            snprintf(where, sizeof(where), "textures[%d]", i);
            int tf = rbl__jsonGet(j, t, "frames");
            if ((tf < 0) || ((j->nodes[tf].type != RBL__J_OBJECT) && (j->nodes[tf].type != RBL__J_ARRAY))) { rbl__atlasErrorf(s, j->nodes[t].start, "%s has no \"frames\" object or array", where); return false; }
            if (!rbl__atlasJsonPage(j, t, meta, file, where) || !rbl__atlasJsonFrames(j, tf, s->pageCount - 1)) return false;
        }
    }
    else if (!rbl__atlasJsonPage(j, meta, meta, file, "meta") || !rbl__atlasJsonFrames(j, frames, s->pageCount - 1)) return false;
    if (meta >= 0) { if (!rbl__atlasJsonTags(j, meta, first) || !rbl__atlasJsonSlices(j, meta, first)) return false; }
    return true;
}

// ---- libGDX text ----------------------------------------------------------------------------
// Up to n comma-separated integers of a value ("948,118,36,78" or "2, 7"); false unless exactly n
static bool rbl__gdxInts(const char *v, const char *end, int *out, int n)
{
    for (int k = 0; k < n; k++)
    {
        while ((v < end) && (*v == ' ')) v++;
        bool neg = false;
        if ((v < end) && (*v == '-')) { neg = true; v++; }
        if (!((v < end) && (*v >= '0') && (*v <= '9'))) return false;
        long x = 0;
        while ((v < end) && (*v >= '0') && (*v <= '9')) { x = x*10 + (*v - '0'); if (x > 1000000000L) return false; v++; }
        out[k] = (int)(neg? -x : x);
        while ((v < end) && (*v == ' ')) v++;
        if (k + 1 < n) { if (!((v < end) && (*v == ','))) return false; v++; }
    }
    return v == end;
}

typedef struct rbl__GdxRegion { int xy[2], size[2], orig[2], offset[2], split[4], index, degrees; bool hasXY, hasSize, hasOrig, hasSplit, hasPad; } rbl__GdxRegion;

static bool rbl__gdxFinish(rbl__AtlasState *s, const char *name, const rbl__GdxRegion *r)
{
    if (!r->hasXY || !r->hasSize) { rbl__atlasError(s, "region \"%s\": no xy/size or bounds", name, -1); return false; }
    RBL__ATLAS_GROW(s, s->frames, s->frameCount, s->frameCap, RblAtlasFrame, "frames", return false);
    RblAtlasFrame *f = &s->frames[s->frameCount];
    memset(f, 0, sizeof(*f));
    f->name = name; f->page = s->pageCount - 1; f->index = r->index;
    float w = (float)r->size[0], h = (float)r->size[1];
    f->block = rbl__rect((float)r->xy[0], (float)r->xy[1], w, h);
    f->size = r->hasOrig? rbl__v2((float)r->orig[0], (float)r->orig[1]) : rbl__v2(w, h);
    // offset from the bottom-left of the original to the bottom-left of the packed part
    f->trim = rbl__rect((float)r->offset[0], f->size.y - (float)r->offset[1] - h, w, h);
    f->pivot = rbl__v2(0.5f, 1.0f);
    // split: left, right, top, bottom insets of the packed part -> its centre, in canvas pixels
    if (r->hasSplit)
    {
        const int *q = r->split;
        if ((q[0] < 0) || (q[1] < 0) || (q[2] < 0) || (q[3] < 0) || (q[0] + q[1] > r->size[0]) || (q[2] + q[3] > r->size[1]))
        { rbl__atlasError(s, "region \"%s\": split insets outside it", name, -1); return false; }
        f->center = rbl__rect(f->trim.x + (float)q[0], f->trim.y + (float)q[2], w - (float)(q[0] + q[1]), h - (float)(q[2] + q[3]));
    }
    s->ignoredPads += r->hasPad;
    // stored turned `degrees` counter-clockwise: 90 and 270 occupy an h x w block; 90 and 180 are
    // the clockwise convention plus a half turn (both extents negated)
    int d = r->degrees;
    if (!rbl__atlasFinishFrame(s, f, (d == 90) || (d == 270), (d == 90) || (d == 180), &s->pages[s->pageCount - 1])) return false;
    s->frameCount++;
    return true;
}

// Stable order key for grouping: regions sharing a name together (first appearance), by index
typedef struct rbl__GdxKey { const char *name; int pos, group, index; } rbl__GdxKey;
static int rbl__gdxByName(const void *a, const void *b)
{
    const rbl__GdxKey *x = (const rbl__GdxKey *)a, *y = (const rbl__GdxKey *)b;
    int c = strcmp(x->name, y->name);
    return (c != 0)? c : ((x->pos > y->pos) - (x->pos < y->pos));
}
static int rbl__gdxByGroup(const void *a, const void *b)
{
    const rbl__GdxKey *x = (const rbl__GdxKey *)a, *y = (const rbl__GdxKey *)b;
    if (x->group != y->group) return (x->group > y->group) - (x->group < y->group);
    if (x->index != y->index) return (x->index > y->index) - (x->index < y->index);
    return (x->pos > y->pos) - (x->pos < y->pos);
}

// libGDX: regions named alike with index >= 0 become one tag in index order (the frames move so
// that each tag is a contiguous run; everything else keeps file order; libGDX has no polygons)
static bool rbl__gdxGroup(rbl__AtlasState *s)
{
    int n = s->frameCount;
    bool any = false;
    for (int i = 0; i < n; i++) any = any || (s->frames[i].index >= 0);
    if (!any) return true;
    rbl__GdxKey *keys = (rbl__GdxKey *)RBL_MALLOC((size_t)n*sizeof(rbl__GdxKey));
    RblAtlasFrame *sorted = (RblAtlasFrame *)RBL_MALLOC((size_t)n*sizeof(RblAtlasFrame));
    if ((keys == NULL) || (sorted == NULL)) { RBL_FREE(keys); RBL_FREE(sorted); rbl__atlasError(s, "out of memory%s", NULL, -1); return false; }
    for (int i = 0; i < n; i++) { keys[i].name = s->frames[i].name; keys[i].pos = i; keys[i].index = s->frames[i].index; }
    qsort(keys, (size_t)n, sizeof(rbl__GdxKey), rbl__gdxByName);
    for (int i = 0; i < n; i++) keys[i].group = ((i > 0) && (strcmp(keys[i].name, keys[i - 1].name) == 0))? keys[i - 1].group : keys[i].pos;
    qsort(keys, (size_t)n, sizeof(rbl__GdxKey), rbl__gdxByGroup);
    for (int i = 0; i < n; i++) sorted[i] = s->frames[keys[i].pos];
    memcpy(s->frames, sorted, (size_t)n*sizeof(RblAtlasFrame));
    bool ok = true;
    for (int i = 0; (i < n) && ok; )
    {
        int e = i;
        while ((e + 1 < n) && (keys[e + 1].group == keys[i].group)) e++;
        int from = i;
        while ((from <= e) && (s->frames[from].index < 0)) from++;
        if (from <= e)
        {
            ok = true; RBL__ATLAS_GROW(s, s->tags, s->tagCount, s->tagCap, RblAtlasTag, "tags", ok = false; break);
            if (ok)
            {
                RblAtlasTag *t = &s->tags[s->tagCount++];
                t->name = s->frames[from].name; t->from = from; t->to = e; t->direction = RBL_SPRITE_FORWARD; t->repeat = 0;
            }
        }
        i = e + 1;
    }
    RBL_FREE(keys); RBL_FREE(sorted);
    return ok;
}

// Field names libGDX writes (page fields before the first region, region fields after). A line
// with a colon is a field when it is indented (the old form indents every region field), when its
// key is one of these, or when the next line is not a region field; otherwise it names a region,
// colons and all ("ui:button" followed by "bounds:...")
static bool rbl__gdxKnownKey(const char *k, size_t kl, bool page)
{
    static const char *const pageKeys[] = { "size", "format", "filter", "repeat", "pma" };
    static const char *const regionKeys[] = { "rotate", "xy", "size", "orig", "offset", "index", "bounds", "offsets", "split", "pad" };
    const char *const *keys = page? pageKeys : regionKeys;
    int n = page? 5 : 10;
    for (int i = 0; i < n; i++) if ((strlen(keys[i]) == kl) && (memcmp(keys[i], k, kl) == 0)) return true;
    return false;
}

// Whether the first non-blank line from p on is a region field (indented, or a region key and a colon)
static bool rbl__gdxRegionFieldNext(const char *p, const char *end)
{
    while (p < end)
    {
        const char *a = p;
        while ((a < end) && ((*a == ' ') || (*a == '\t'))) a++;
        const char *eol = a;
        while ((eol < end) && (*eol != '\n')) eol++;
        const char *b = eol;
        while ((b > a) && ((b[-1] == ' ') || (b[-1] == '\t') || (b[-1] == '\r'))) b--;
        if (a == b) return false;        // a blank line ends the page
        const char *colon = (const char *)memchr(a, ':', (size_t)(b - a));
        if (colon == NULL) return false;
        if (a > p) return true;
        const char *ke = colon;
        while ((ke > a) && ((ke[-1] == ' ') || (ke[-1] == '\t'))) ke--;
        return rbl__gdxKnownKey(a, (size_t)(ke - a), false);
    }
    return false;
}

static bool rbl__atlasParseGdx(rbl__AtlasState *s, const char *text, int size, const char *file)
{
    const char *p = text, *end = text + size;
    bool expectPage = true;
    const char *region = NULL;
    rbl__GdxRegion r;
    memset(&r, 0, sizeof(r));
    int lineNo = 0;
    while (p < end)
    {
        const char *eol = p;
        while ((eol < end) && (*eol != '\n')) eol++;
        const char *a = p, *b = eol;
        p = (eol < end)? eol + 1 : end;
        lineNo++;
        const char *lineStart = a;
        while ((a < b) && ((*a == ' ') || (*a == '\t'))) a++;
        while ((b > a) && ((b[-1] == ' ') || (b[-1] == '\t') || (b[-1] == '\r'))) b--;
        bool indented = (a > lineStart);
        for (const char *c = a; c < b; c++) if ((unsigned char)*c < 0x20 && (*c != '\t')) { rbl__atlasErrorf(s, -1, "libGDX: control character on line %d", lineNo); return false; }
        if (a == b)     // blank line: a page ends (its last region with it)
        {
            if (region != NULL) { if (!rbl__gdxFinish(s, region, &r)) return false; region = NULL; }
            expectPage = true;
            continue;
        }
        if (expectPage)
        {
            const char *written = rbl__atlasPoolCopy(s, a, (size_t)(b - a)), *image = written;
            if ((written != NULL) && (file != NULL)) image = rbl__atlasFindFile(s, file, written, file, "", "sheet");
            RblAtlasPage *page = (image == NULL)? NULL : rbl__atlasAddPage(s, image, 0, 0);
            if ((page == NULL) || ((file != NULL) && !rbl__atlasProbeNormal(s, page))) return false;
            expectPage = false;
            continue;
        }
        const char *colon = (const char *)memchr(a, ':', (size_t)(b - a));
        const char *k = a, *ke = colon;
        if (colon != NULL) { while ((ke > k) && ((ke[-1] == ' ') || (ke[-1] == '\t'))) ke--; }
        size_t kl = (colon != NULL)? (size_t)(ke - k) : 0;
        if ((colon == NULL) || !(indented || rbl__gdxKnownKey(k, kl, region == NULL) || !rbl__gdxRegionFieldNext(p, end)))      // a region name
        {
            if (region != NULL) { if (!rbl__gdxFinish(s, region, &r)) return false; }
            region = rbl__atlasPoolCopy(s, a, (size_t)(b - a));
            if (region == NULL) return false;
            memset(&r, 0, sizeof(r)); r.index = -1;
            continue;
        }
        const char *v = colon + 1;
        while ((v < b) && (*v == ' ')) v++;
        #define RBL__KEY(word) ((kl == sizeof(word) - 1) && (memcmp(k, word, kl) == 0))
        bool ok = true;
        int q[4];
        size_t vl = (size_t)(b - v);
        if (region == NULL)     // page fields: size and pma are read (format, filter, repeat: the texture's own)
        {
            RblAtlasPage *page = &s->pages[s->pageCount - 1];
            if (RBL__KEY("size"))
            {
                ok = rbl__gdxInts(v, b, q, 2) && (q[0] > 0) && (q[1] > 0) && (q[0] <= RBL__ATLAS_MAX_COORD) && (q[1] <= RBL__ATLAS_MAX_COORD);
                if (!ok) { rbl__atlasErrorf(s, -1, "libGDX: page size on line %d is not whole texels 1..%g", lineNo, RBL__ATLAS_MAX_COORD); return false; }
                page->width = q[0]; page->height = q[1];
            }
            else if (RBL__KEY("pma"))
            {
                if ((vl == 4) && (memcmp(v, "true", 4) == 0)) page->premultiplied = true;
                else if ((vl == 5) && (memcmp(v, "false", 5) == 0)) page->premultiplied = false;
                else ok = false;
            }
        }
        else if (RBL__KEY("rotate"))
        {
            // true = 90; any multiple of 90 degrees (counter-clockwise, as libGDX and Spine store it)
            int d = 0;
            if ((vl == 4) && (memcmp(v, "true", 4) == 0)) d = 90;
            else if ((vl == 5) && (memcmp(v, "false", 5) == 0)) d = 0;
            else ok = rbl__gdxInts(v, b, &d, 1) && (d%90 == 0);
            r.degrees = ((d%360) + 360)%360;
        }
        else if (RBL__KEY("xy")) { ok = rbl__gdxInts(v, b, r.xy, 2); r.hasXY = true; }
        else if (RBL__KEY("size")) { ok = rbl__gdxInts(v, b, r.size, 2); r.hasSize = true; }
        else if (RBL__KEY("orig")) { ok = rbl__gdxInts(v, b, r.orig, 2); r.hasOrig = true; }
        else if (RBL__KEY("offset")) ok = rbl__gdxInts(v, b, r.offset, 2);
        else if (RBL__KEY("index")) ok = rbl__gdxInts(v, b, &r.index, 1) && (r.index >= -1);
        else if (RBL__KEY("bounds"))
        {
            ok = rbl__gdxInts(v, b, q, 4);
            r.xy[0] = q[0]; r.xy[1] = q[1]; r.size[0] = q[2]; r.size[1] = q[3]; r.hasXY = r.hasSize = true;
        }
        else if (RBL__KEY("offsets"))
        {
            ok = rbl__gdxInts(v, b, q, 4);
            r.offset[0] = q[0]; r.offset[1] = q[1]; r.orig[0] = q[2]; r.orig[1] = q[3]; r.hasOrig = true;
        }
        else if (RBL__KEY("split")) { ok = rbl__gdxInts(v, b, r.split, 4) && (abs(r.split[0]) <= RBL__ATLAS_MAX_COORD) && (abs(r.split[1]) <= RBL__ATLAS_MAX_COORD) && (abs(r.split[2]) <= RBL__ATLAS_MAX_COORD) && (abs(r.split[3]) <= RBL__ATLAS_MAX_COORD); r.hasSplit = true; }
        else if (RBL__KEY("pad")) { ok = rbl__gdxInts(v, b, q, 4); r.hasPad = true; }
        #undef RBL__KEY
        for (int c = 0; c < 2; c++) if ((abs(r.xy[c]) > RBL__ATLAS_MAX_COORD) || (abs(r.size[c]) > RBL__ATLAS_MAX_COORD) || (abs(r.orig[c]) > RBL__ATLAS_MAX_COORD) || (abs(r.offset[c]) > RBL__ATLAS_MAX_COORD)) ok = false;
        if (!ok) { rbl__atlasErrorf(s, -1, "libGDX: bad %.*s value on line %d", (int)((kl < 32)? kl : 32), k, lineNo); return false; }
    }
    if ((region != NULL) && !rbl__gdxFinish(s, region, &r)) return false;
    if (s->frameCount == 0) { rbl__atlasError(s, "libGDX: no regions%s", NULL, -1); return false; }
    return rbl__gdxGroup(s);
}

// Parses one text into s (appending its pages and frames); format in/out. file: the text's path
// (RblLoadAtlas), NULL from memory
static bool rbl__atlasParse(rbl__AtlasState *s, const char *text, int size, int *format, const char *file, char ***related, int *relatedCount)
{
    // decoded strings never outgrow their raw text (sheet paths have blocks of their own)
    if (!rbl__atlasPoolBegin(s, 2*(size_t)size + 64)) return false;
    int f = *format;     // TexturePacker and Aseprite read alike (the caller's name is kept); AUTO: detected
    if (f == RBL_ATLAS_AUTO)
    {
        int i = 0;
        if ((size >= 3) && ((unsigned char)text[0] == 0xEF) && ((unsigned char)text[1] == 0xBB) && ((unsigned char)text[2] == 0xBF)) i = 3;
        while ((i < size) && ((text[i] == ' ') || (text[i] == '\t') || (text[i] == '\n') || (text[i] == '\r'))) i++;
        f = ((i < size) && (text[i] == '{'))? RBL_ATLAS_AUTO : RBL_ATLAS_LIBGDX;   // JSON: told apart by its meta
    }
    if (f == RBL_ATLAS_LIBGDX) { *format = f; return rbl__atlasParseGdx(s, text, size, file); }
    rbl__Json j;
    bool ok = rbl__atlasParseJson(s, text, size, file, &f, &j);
    if (ok && (related != NULL))
    {
        int packs = rbl__jsonGet(&j, rbl__jsonGet(&j, 0, "meta"), "related_multi_packs");
        if ((packs >= 0) && (j.nodes[packs].type == RBL__J_ARRAY))
            for (int k = packs + 1, i = 0; (i < j.nodes[packs].count) && ok; i++, k = j.nodes[k].next)
            {
                const char *name = rbl__jsonText(&j, k);
                if (name == NULL) { rbl__atlasError(s, "related_multi_packs holds a non-string%s", NULL, j.nodes[k].start); ok = false; break; }
                // plain file names beside the atlas only: a pack never leads the loader elsewhere
                if ((name[0] == 0) || (name[0] == '.') || (strchr(name, '/') != NULL) || (strchr(name, '\\') != NULL)) { rbl__atlasError(s, "related pack \"%s\" is not a file name beside the atlas", name, j.nodes[k].start); ok = false; break; }
                if (*relatedCount >= RBL__ATLAS_MAX_PAGES) { rbl__atlasErrorf(s, -1, "more than %d sheets", RBL__ATLAS_MAX_PAGES); ok = false; break; }
                (*related)[(*relatedCount)++] = (char *)name;
            }
    }
    RBL_FREE(j.nodes);
    *format = f;
    return ok;
}

// Orders edges by their vertex pair (smaller first), then by triangle corner
static int rbl__compareEdges(const void *a, const void *b)
{
    const unsigned int *p = (const unsigned int *)a, *q = (const unsigned int *)b;
    for (int i = 0; i < 3; i++) if (p[i] != q[i]) return (p[i] < q[i])? -1 : 1;
    return 0;
}

// Scratch of the polygon preparation (grown as needed, freed at its end)
typedef struct rbl__PolyScratch {
    Vector2 *frac; int fracCount, fracCap;       // every polygon's vertices, then its cut points
    unsigned int *slots; int slotCount, slotCap; // every polygon's slots, both cuts
    unsigned int *tri, *piece, *edges; int triCap, pieceCap, edgeCap;
} rbl__PolyScratch;

static bool rbl__polyReserve(void **array, int *cap, int need, size_t elem)
{
    if (need <= *cap) return true;
    int n = (*cap > 0)? *cap : 64;
    while (n < need) { if (n > 0x3FFFFFFF/2) return false; n *= 2; }
    void *p = RBL_REALLOC(*array, (size_t)n*elem);
    if (p == NULL) return false;
    *array = p;
    *cap = n;
    return true;
}

// Triangles tri[0..n) (vertex indices from first), cut along diagonal d into pieces wholly on one
// side (a new vertex where an edge crosses it, exactly on it), appended to x->piece; their count or -1
static int rbl__polyCut(rbl__PolyScratch *x, int first, int n, int d)
{
    int count = 0;
    for (int t = 0; t < n; t++)
    {
        const unsigned int *v = x->tri + 3*t;
        double f[3];
        int neg = 0, pos = 0;
        for (int c = 0; c < 3; c++)
        {
            const Vector2 p = x->frac[first + (int)v[c]];
            f[c] = (d == 0)? (double)p.x - p.y : (double)p.x + p.y - 1.0;
            neg += f[c] < 0.0; pos += f[c] > 0.0;
        }
        unsigned int poly[2][4];
        int len[2] = { 0, 0 };
        if ((neg == 0) || (pos == 0)) { poly[0][0] = v[0]; poly[0][1] = v[1]; poly[0][2] = v[2]; len[0] = 3; }
        else
        {
            // Walk the edges: each vertex to its side, a crossing to both (Sutherland-Hodgman)
            for (int c = 0; c < 3; c++)
            {
                int e = (c + 1)%3;
                if (f[c] >= 0.0) poly[0][len[0]++] = v[c];
                if (f[c] <= 0.0) poly[1][len[1]++] = v[c];
                if ((f[c] < 0.0) != (f[e] < 0.0) && (f[c] != 0.0) && (f[e] != 0.0))
                {
                    if (!rbl__polyReserve((void **)&x->frac, &x->fracCap, x->fracCount + 1, sizeof(Vector2))) return -1;
                    const Vector2 p = x->frac[first + (int)v[c]], q = x->frac[first + (int)v[e]];
                    double k = f[c]/(f[c] - f[e]), a = p.x + k*((double)q.x - p.x);
                    x->frac[x->fracCount] = rbl__v2((float)a, (float)((d == 0)? a : 1.0 - a));   // on the diagonal
                    unsigned int at = (unsigned int)(x->fracCount++ - first);
                    poly[0][len[0]++] = at; poly[1][len[1]++] = at;
                }
            }
        }
        for (int h = 0; h < 2; h++)
            for (int c = 1; c + 1 < len[h]; c++)
            {
                if (!rbl__polyReserve((void **)&x->piece, &x->pieceCap, 3*(count + 1), sizeof(unsigned int))) return -1;
                unsigned int *o = x->piece + 3*count;
                o[0] = poly[h][0]; o[1] = poly[h][c]; o[2] = poly[h][c + 1];
                const Vector2 A = x->frac[first + (int)o[0]], B = x->frac[first + (int)o[1]], C = x->frac[first + (int)o[2]];
                if (((double)B.x - A.x)*((double)C.y - A.y) - ((double)C.x - A.x)*((double)B.y - A.y) != 0.0) count++;
            }
    }
    return count;
}

// Pieces x->piece[0..n) paired across shared edges into slots of two (a, b, c) + (a, c, d), the
// unpaired alone (a, b, c, c), appended to x->slots; false when out of memory
static bool rbl__polyPair(rbl__PolyScratch *x, int n)
{
    if (!rbl__polyReserve((void **)&x->edges, &x->edgeCap, 3*n*3 + 3, sizeof(unsigned int)) ||
        !rbl__polyReserve((void **)&x->slots, &x->slotCap, 4*(x->slotCount + n), sizeof(unsigned int))) return false;
    unsigned char *paired = (unsigned char *)RBL_MALLOC((size_t)n + 1);
    if (paired == NULL) return false;
    const unsigned int *tri = x->piece;
    for (int t = 0; t < n; t++)
    {
        paired[t] = 0;
        for (int e = 0; e < 3; e++)
        {
            unsigned int u = tri[3*t + e], w = tri[3*t + (e + 1)%3], *o = x->edges + 3*(3*t + e);
            o[0] = (u < w)? u : w; o[1] = (u < w)? w : u; o[2] = (unsigned int)(3*t + e);
        }
    }
    qsort(x->edges, (size_t)n*3, 3*sizeof(unsigned int), rbl__compareEdges);
    for (int t = 0; t < n; t++)
    {
        if (paired[t]) continue;
        paired[t] = 1;
        unsigned int *o = x->slots + 4*x->slotCount++;
        o[0] = tri[3*t]; o[1] = tri[3*t + 1]; o[2] = tri[3*t + 2]; o[3] = tri[3*t + 2];
        // A neighbour across one of t's edges (u -> w in t, w -> u in it): the slot starts at w
        for (int e = 0; e < 3; e++)
        {
            unsigned int u = tri[3*t + e], w = tri[3*t + (e + 1)%3], lo0 = (u < w)? u : w, hi0 = (u < w)? w : u;
            int lo = 0, hi = 3*n;
            while (lo < hi)
            {
                int mid = (lo + hi)/2;
                const unsigned int *m = x->edges + 3*mid;
                if ((m[0] < lo0) || ((m[0] == lo0) && (m[1] < hi0))) lo = mid + 1; else hi = mid;
            }
            int found = -1;
            for (int k = lo; (k < 3*n) && (x->edges[3*k] == lo0) && (x->edges[3*k + 1] == hi0) && (found < 0); k++)
            {
                int other = (int)x->edges[3*k + 2]/3, oe = (int)x->edges[3*k + 2]%3;
                if (paired[other] || (tri[3*other + oe] != w)) continue;       // taken, or the same way round (folded)
                found = other;
                o[3] = tri[3*other + (oe + 2)%3];
            }
            if (found < 0) continue;
            paired[found] = 1;
            // t from w: (w, x, u) with x its third vertex; the neighbour (w, u, d)
            o[0] = w; o[1] = tri[3*t + (e + 2)%3]; o[2] = u;
            break;
        }
    }
    RBL_FREE(paired);
    return true;
}

// The draw paths' form of every polygon (rbl__Polygon): vertices as fractions of the frame's source
// (from the file's texels), triangles of zero area dropped, the rest wound as the quad's triangles are
// (clockwise in texel space, y down: the quad's (0,1,2) seen upright), cut along each frame diagonal
// (rbl__polyCut) and as they are, each paired into slots (rbl__polyPair); then registered
static bool rbl__atlasPolygonsPrepare(rbl__AtlasState *s)
{
    if (s->polygonCount == 0) return true;
    rbl__PolyScratch x;
    memset(&x, 0, sizeof(x));
    s->polyDraw = (rbl__Polygon *)RBL_CALLOC((size_t)s->polygonCount, sizeof(rbl__Polygon));
    int *firstSlot = (int *)RBL_MALLOC((size_t)s->polygonCount*3*sizeof(int) + sizeof(int)), *firstFrac = (int *)RBL_MALLOC((size_t)s->polygonCount*sizeof(int) + sizeof(int));
    bool ok = (s->polyDraw != NULL) && (firstSlot != NULL) && (firstFrac != NULL);
    for (int i = 0; ok && (i < s->polygonCount); i++)
    {
        const RblAtlasPolygon *p = &s->polygons[i];
        const RblAtlasFrame *f = &s->frames[s->polygonRefs[i].frame];
        const int first = x.fracCount;
        firstFrac[i] = first;
        ok = rbl__polyReserve((void **)&x.frac, &x.fracCap, first + p->vertexCount, sizeof(Vector2)) &&
             rbl__polyReserve((void **)&x.tri, &x.triCap, p->indexCount, sizeof(unsigned int));
        if (!ok) break;
        const double sx = f->source.x, sy = f->source.y, sw = fabs((double)f->source.width), sh = fabs((double)f->source.height);
        for (int v = 0; v < p->vertexCount; v++)
        {
            double a = (sw > 0.0)? ((double)p->uvs[v].x - sx)/sw : 0.0, b = (sh > 0.0)? ((double)p->uvs[v].y - sy)/sh : 0.0;
            x.frac[first + v] = rbl__v2((float)fmin(fmax(a, 0.0), 1.0), (float)fmin(fmax(b, 0.0), 1.0));
        }
        x.fracCount += p->vertexCount;
        int n = 0;
        for (int t = 0; t < p->indexCount/3; t++)
        {
            unsigned int c0 = p->indices[3*t], c1 = p->indices[3*t + 1], c2 = p->indices[3*t + 2];
            const Vector2 A = x.frac[first + (int)c0], B = x.frac[first + (int)c1], C = x.frac[first + (int)c2];
            double area2 = ((double)B.x - A.x)*((double)C.y - A.y) - ((double)C.x - A.x)*((double)B.y - A.y);
            if (area2 == 0.0) continue;
            x.tri[3*n] = c0; x.tri[3*n + 1] = (area2 < 0.0)? c1 : c2; x.tri[3*n + 2] = (area2 < 0.0)? c2 : c1;
            n++;
        }
        for (int d = 0; ok && (d < 3); d++)
        {
            int pieces = (d < 2)? rbl__polyCut(&x, first, n, d) : n;
            if ((d == 2) && rbl__polyReserve((void **)&x.piece, &x.pieceCap, 3*n + 3, sizeof(unsigned int))) memcpy(x.piece, x.tri, 3*(size_t)n*sizeof(unsigned int));
            else if (d == 2) pieces = -1;
            firstSlot[3*i + d] = x.slotCount;
            ok = (pieces >= 0) && rbl__polyPair(&x, pieces);
            if (ok) { s->polyDraw[i].triangles[d] = pieces; s->polyDraw[i].slotCount[d] = x.slotCount - firstSlot[3*i + d]; }
        }
    }
    if (ok)
    {
        // The scratch becomes the atlas's (the rows stopped moving)
        s->polyFrac = x.frac; s->polySlots = x.slots;
        x.frac = NULL; x.slots = NULL;
        for (int i = 0; i < s->polygonCount; i++)
        {
            // (no rows at all when every triangle is degenerate: NULL, never an offset from it)
            s->polyDraw[i].frac = (s->polyFrac != NULL)? s->polyFrac + firstFrac[i] : NULL;
            for (int d = 0; d < 3; d++) s->polyDraw[i].slots[d] = (s->polySlots != NULL)? s->polySlots + 4*(size_t)firstSlot[3*i + d] : NULL;
        }
    }
    RBL_FREE(x.frac); RBL_FREE(x.slots); RBL_FREE(x.tri); RBL_FREE(x.piece); RBL_FREE(x.edges);
    RBL_FREE(firstSlot); RBL_FREE(firstFrac);
    if (!ok) { rbl__atlasErrorf(s, -1, "out of memory for %d polygons", s->polygonCount); return false; }
    s->polyFirst = rbl__polygonRegister(s->polyDraw, s->polygonCount);
    if (s->polyFirst == 0u) { rbl__atlasErrorf(s, -1, "no room for %d more polygon frames (%d handles, RBL_FRAME_POLYGON) or out of memory", s->polygonCount, (int)RBL__POLYGON_HANDLES); return false; }
    return true;
}

static RblAtlas rbl__atlasPublish(rbl__AtlasState *s, int format)
{
    RblAtlas a;
    memset(&a, 0, sizeof(a));
    s->format = format;
    // the tables stopped moving: polygons point into their rows, frames at their polygons
    for (int i = 0; i < s->polygonCount; i++)
    {
        RblAtlasPolygon *p = &s->polygons[i];
        const rbl__AtlasPolyRef *r = &s->polygonRefs[i];
        p->vertices = s->polyPoints + r->vertex;
        p->uvs = s->polyPoints + r->vertex + p->vertexCount;
        p->indices = s->polyIndices + r->index;
        s->frames[r->frame].polygon = p;
    }
    if (!rbl__atlasPolygonsPrepare(s)) return a;
    for (int i = 0; i < s->polygonCount; i++) s->frames[s->polygonRefs[i].frame].flags |= (s->polyFirst + (unsigned int)i) << RBL__POLYGON_SHIFT;
    a.id = rbl__liveAdd(s);
    if (a.id == 0) return a;            // out of memory: the caller fails the load
    a.format = format;
    a.frameCount = s->frameCount; a.tagCount = s->tagCount; a.pageCount = s->pageCount; a.sliceCount = s->sliceCount;
    a.frames = s->frames; a.tags = s->tags; a.pages = s->pages; a.slices = s->slices;
    a.state = s;
    return a;
}

// What a loaded atlas leaves unread, said once (LOG_INFO: the atlas is fine)
static void rbl__atlasReportIgnored(const rbl__AtlasState *s, const char *fn, const char *what)
{
    if (s->ignoredPads > 0) TraceLog(LOG_INFO, "RBL: %s: %s: libGDX pad (9-slice content padding) of %i regions ignored", fn, what, s->ignoredPads);
}

static RblAtlas rbl__atlasFail(rbl__AtlasState *s, const char *fn, const char *what)
{
    RblAtlas a;
    memset(&a, 0, sizeof(a));
    TraceLog(LOG_WARNING, "RBL: %s: %s: %s", fn, what, ((s != NULL) && (s->error[0] != 0))? s->error : "out of memory");
    rbl__atlasFree(s);
    rbl__tidyAfterClose();
    return a;
}

RblAtlas RblLoadAtlasFromMemory(const char *text, int size, int format)
{
    RblAtlas none;
    memset(&none, 0, sizeof(none));
    if ((text == NULL) || (size <= 0) || (size > (1 << 28))) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlasFromMemory: text NULL or size outside 1..2^28"); return none; }
    if ((format < RBL_ATLAS_AUTO) || (format > RBL_ATLAS_LIBGDX)) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlasFromMemory: unknown format %i", format); return none; }
    rbl__AtlasState *s = (rbl__AtlasState *)RBL_CALLOC(1, sizeof(rbl__AtlasState));
    if (s == NULL) return rbl__atlasFail(s, "RblLoadAtlasFromMemory", "atlas");
    int f = format;
    if (!rbl__atlasParse(s, text, size, &f, NULL, NULL, NULL)) return rbl__atlasFail(s, "RblLoadAtlasFromMemory", "atlas");
    if (s->frameCount == 0) { rbl__atlasError(s, "no frames%s", NULL, -1); return rbl__atlasFail(s, "RblLoadAtlasFromMemory", "atlas"); }
    RblAtlas a = rbl__atlasPublish(s, f);
    if (a.state == NULL) return rbl__atlasFail(s, "RblLoadAtlasFromMemory", "atlas");
    rbl__atlasReportIgnored(s, "RblLoadAtlasFromMemory", "atlas");
    return a;
}

RblAtlas RblLoadAtlas(const char *fileName)
{
    RblAtlas none;
    memset(&none, 0, sizeof(none));
    if ((fileName == NULL) || (fileName[0] == 0)) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlas: fileName NULL or empty"); return none; }
    rbl__AtlasState *s = (rbl__AtlasState *)RBL_CALLOC(1, sizeof(rbl__AtlasState));
    if (s == NULL) return rbl__atlasFail(s, "RblLoadAtlas", fileName);
    // the folder of the file: sheets and related packs are named relative to it
    size_t fl = strlen(fileName), dl = fl;
    while ((dl > 0) && (fileName[dl - 1] != '/') && (fileName[dl - 1] != '\\')) dl--;
    char path[2048];
    if (fl >= sizeof(path)) { rbl__atlasErrorf(s, -1, "path longer than %d bytes", (int)sizeof(path) - 1); return rbl__atlasFail(s, "RblLoadAtlas", fileName); }
    char *relatedStore[RBL__ATLAS_MAX_PAGES], **related = relatedStore;
    int relatedCount = 0, done = 0, format = RBL_ATLAS_AUTO;
    const char *loaded[RBL__ATLAS_MAX_PAGES + 1];
    memcpy(path, fileName, fl + 1);
    const char *next = fileName;
    for (;;)
    {
        int bytes = 0;
        unsigned char *data = LoadFileData(path, &bytes);
        if ((data == NULL) || (bytes <= 0)) { if (data != NULL) UnloadFileData(data); rbl__atlasError(s, "cannot read \"%s\"", path, -1); return rbl__atlasFail(s, "RblLoadAtlas", fileName); }
        int f = (done == 0)? RBL_ATLAS_AUTO : format;
        bool ok = rbl__atlasParse(s, (const char *)data, bytes, &f, path, &related, &relatedCount);
        UnloadFileData(data);
        if (!ok) return rbl__atlasFail(s, "RblLoadAtlas", path);
        if (done == 0) format = f;
        loaded[done++] = next;
        // next related pack not loaded yet (each pack lists the others)
        next = NULL;
        for (int i = 0; (i < relatedCount) && (next == NULL); i++)
        {
            bool seen = false;
            for (int k = 1; k < done; k++) seen = seen || (strcmp(loaded[k], related[i]) == 0);
            const char *base = fileName + dl;
            if (!seen && (strcmp(related[i], base) != 0)) next = related[i];
        }
        if (next == NULL) break;
        if (done > RBL__ATLAS_MAX_PAGES) { rbl__atlasErrorf(s, -1, "more than %d sheets", RBL__ATLAS_MAX_PAGES); return rbl__atlasFail(s, "RblLoadAtlas", fileName); }
        if (dl + strlen(next) + 1 >= sizeof(path)) { rbl__atlasErrorf(s, -1, "path longer than %d bytes", (int)sizeof(path) - 1); return rbl__atlasFail(s, "RblLoadAtlas", fileName); }
        memcpy(path, fileName, dl); memcpy(path + dl, next, strlen(next) + 1);
    }
    if (s->frameCount == 0) { rbl__atlasError(s, "no frames%s", NULL, -1); return rbl__atlasFail(s, "RblLoadAtlas", fileName); }
    RblAtlas a = rbl__atlasPublish(s, format);
    if (a.state == NULL) return rbl__atlasFail(s, "RblLoadAtlas", fileName);
    rbl__atlasReportIgnored(s, "RblLoadAtlas", fileName);
    return a;
}

bool RblIsAtlasValid(RblAtlas atlas) { return rbl__atlasLive(&atlas); }

void RblUnloadAtlas(RblAtlas *atlas)
{
    if (atlas == NULL) { TraceLog(LOG_WARNING, "RBL: RblUnloadAtlas: NULL atlas"); return; }
    if (!rbl__atlasLive(atlas))
    {
        TraceLog(LOG_WARNING, "RBL: RblUnloadAtlas: atlas %s", ((atlas->id != 0) || (atlas->state != NULL))? "already unloaded (a stale copy)" : "not loaded (zero, or unloaded before)");
        memset(atlas, 0, sizeof(*atlas));
        return;
    }
    rbl__liveRemove(atlas->id);
    rbl__atlasFree(atlas->state);
    memset(atlas, 0, sizeof(*atlas));
    rbl__tidyAfterClose();
}

// The live state of an atlas argument, or NULL after one line under fn
static const rbl__AtlasState *rbl__atlasArg(const RblAtlas *atlas, const char *fn)
{
    if (atlas == NULL) { TraceLog(LOG_WARNING, "RBL: %s: NULL atlas", fn); return NULL; }
    if (!rbl__atlasLive(atlas)) { TraceLog(LOG_WARNING, "RBL: %s: atlas not loaded (zero, unloaded or a stale copy)", fn); return NULL; }
    return atlas->state;
}

int RblAtlasFindFrame(const RblAtlas *atlas, const char *name)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblAtlasFindFrame");
    if (s == NULL) return -1;
    if (name == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasFindFrame: NULL name"); return -1; }
    for (int i = 0; i < s->frameCount; i++) if (strcmp(s->frames[i].name, name) == 0) return i;
    return -1;
}

int RblAtlasFindTag(const RblAtlas *atlas, const char *name)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblAtlasFindTag");
    if (s == NULL) return -1;
    if (name == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasFindTag: NULL name"); return -1; }
    for (int i = 0; i < s->tagCount; i++) if (strcmp(s->tags[i].name, name) == 0) return i;
    return -1;
}

// World units per sheet texel: worldScale per pixel of the art at scale 1 (a sheet exported at
// meta.scale 0.5 has half the texels: its frames come out the size of the full-scale sheet's)
static double rbl__atlasUnit(const rbl__AtlasState *s, const RblAtlasFrame *f, float worldScale)
{
    return (double)worldScale/(double)s->pages[f->page].scale;
}

// Quad of a frame: the trimmed part at its place in the untrimmed frame, pivot as the origin
// (world units from the drawn quad's bottom-left; may lie outside it); k world units per texel
static void rbl__atlasFrameQuad(const RblAtlasFrame *f, double k, Rectangle *source, Vector2 *size, Vector2 *origin, unsigned int *flags)
{
    double px = (double)f->pivot.x*f->size.x, py = (double)f->pivot.y*f->size.y;     // pixels, top-left origin
    *source = f->source;
    *size = rbl__v2((float)(f->trim.width*k), (float)(f->trim.height*k));
    *origin = rbl__v2((float)((px - f->trim.x)*k), (float)(((double)f->trim.y + f->trim.height - py)*k));
    *flags = f->flags;
}

static bool rbl__atlasQuad(const RblAtlas *atlas, int frame, float worldScale, const char *fn, Rectangle *source, Vector2 *size, Vector2 *origin, unsigned int *flags)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, fn);
    if (s == NULL) return false;
    if ((frame < 0) || (frame >= s->frameCount)) { TraceLog(LOG_WARNING, "RBL: %s: frame %i outside 0..%i", fn, frame, s->frameCount - 1); return false; }
    if (!rbl__finite(worldScale) || !(worldScale > 0.0f) || (worldScale > 1e15f)) { TraceLog(LOG_WARNING, "RBL: %s: worldScale must be finite and in (0, 1e15]", fn); return false; }
    rbl__atlasFrameQuad(&s->frames[frame], rbl__atlasUnit(s, &s->frames[frame], worldScale), source, size, origin, flags);
    return true;
}

bool RblAtlasBillboard(const RblAtlas *atlas, int frame, float worldScale, RblBillboard *billboard)
{
    if (billboard == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasBillboard: NULL billboard"); return false; }
    Rectangle src; Vector2 size, origin; unsigned int flags;
    if (!rbl__atlasQuad(atlas, frame, worldScale, "RblAtlasBillboard", &src, &size, &origin, &flags)) return false;
    billboard->source = src; billboard->size = size; billboard->origin = origin;
    billboard->flags = (billboard->flags & ~RBL__FRAME_BITS) | flags;
    return true;
}

bool RblAtlasInstance(const RblAtlas *atlas, int frame, float worldScale, RblInstance *instance)
{
    if (instance == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasInstance: NULL instance"); return false; }
    Rectangle src; Vector2 size, origin; unsigned int flags;
    if (!rbl__atlasQuad(atlas, frame, worldScale, "RblAtlasInstance", &src, &size, &origin, &flags)) return false;
    instance->source = src; instance->size = size; instance->origin = origin;
    instance->flags = (instance->flags & ~RBL__FRAME_BITS) | flags;
    return true;
}

// The source rectangle that shows the part [a0, a1] x [b0, b1] of a frame's trimmed picture
// (fractions: a from its left, b from its top; beyond 0..1 the texture coordinates run on at the
// same rate). Texture x follows the picture's x (upright) or y (stored turned clockwise: x runs up
// the picture unless the height is negated); growing with it or against it (a negated extent).
static Rectangle rbl__atlasSubSource(const RblAtlasFrame *f, double a0, double a1, double b0, double b1)
{
    const Rectangle o = f->source;
    bool rotated = (f->flags & RBL_FRAME_ROTATED) != 0;
    double x0 = rotated? b0 : a0, x1 = rotated? b1 : a1, y0 = rotated? a0 : b0, y1 = rotated? a1 : b1;
    bool forwardX = rotated? (o.height < 0.0f) : (o.width >= 0.0f), forwardY = (rotated? o.width : o.height) >= 0.0f;
    double w = fabs((double)o.width), h = fabs((double)o.height);
    Rectangle r;
    r.x = (float)(o.x + (forwardX? x0 : 1.0 - x1)*w);
    r.y = (float)(o.y + (forwardY? y0 : 1.0 - y1)*h);
    r.width = (float)((x1 - x0)*w*((o.width < 0.0f)? -1.0 : 1.0));
    r.height = (float)((y1 - y0)*h*((o.height < 0.0f)? -1.0 : 1.0));
    return r;
}

// Cross-fade quad of two frames: the union of their trimmed rectangles (pixels from each frame's own
// pivot, y down: the pivots coincide), each frame's source stretched to the union (texture
// coordinates run on past its trim at the same rate) and its trim as a clip rectangle of the union.
// Frames of equal trim and pivot give the single frame's quad and source exactly (no clip)
static bool rbl__atlasFadeQuad(const RblAtlas *atlas, int frame, int nextFrame, float weight, float worldScale, const char *fn,
                               Rectangle *source, Vector2 *size, Vector2 *origin, unsigned int *flags, RblFade *fade)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, fn);
    if (s == NULL) return false;
    if ((frame < 0) || (frame >= s->frameCount) || (nextFrame < 0) || (nextFrame >= s->frameCount)) { TraceLog(LOG_WARNING, "RBL: %s: frames %i, %i not both in 0..%i", fn, frame, nextFrame, s->frameCount - 1); return false; }
    if (!rbl__finite(weight) || (weight < 0.0f) || (weight > 1.0f)) { TraceLog(LOG_WARNING, "RBL: %s: weight must be in 0..1", fn); return false; }
    if (!rbl__finite(worldScale) || !(worldScale > 0.0f) || (worldScale > 1e15f)) { TraceLog(LOG_WARNING, "RBL: %s: worldScale must be finite and in (0, 1e15]", fn); return false; }
    const RblAtlasFrame *f[2] = { &s->frames[frame], &s->frames[nextFrame] };
    if (f[0]->page != f[1]->page) { TraceLog(LOG_WARNING, "RBL: %s: frames %i and %i lie in different sheets (one texture is sampled)", fn, frame, nextFrame); return false; }
    double r[2][4];                 // left, top, right, bottom
    for (int k = 0; k < 2; k++)
    {
        const Rectangle t = f[k]->trim;
        if (!((t.width > 0.0f) && (t.height > 0.0f))) { TraceLog(LOG_WARNING, "RBL: %s: frame %i has an empty trim", fn, (k == 0)? frame : nextFrame); return false; }
        double px = (double)f[k]->pivot.x*f[k]->size.x, py = (double)f[k]->pivot.y*f[k]->size.y;
        r[k][0] = t.x - px; r[k][1] = t.y - py; r[k][2] = (double)t.x + t.width - px; r[k][3] = (double)t.y + t.height - py;
    }
    double u[4] = { fmin(r[0][0], r[1][0]), fmin(r[0][1], r[1][1]), fmax(r[0][2], r[1][2]), fmax(r[0][3], r[1][3]) };
    double uw = u[2] - u[0], uh = u[3] - u[1], k = rbl__atlasUnit(s, f[0], worldScale);
    Rectangle src[2], clip[2];
    for (int i = 0; i < 2; i++)
    {
        double tw = r[i][2] - r[i][0], th = r[i][3] - r[i][1];
        // The union's edges in the frame's own fractions (0..1 = its trim)
        src[i] = rbl__atlasSubSource(f[i], (u[0] - r[i][0])/tw, (u[2] - r[i][0])/tw, (u[1] - r[i][1])/th, (u[3] - r[i][1])/th);
        clip[i].x = (float)((r[i][0] - u[0])/uw); clip[i].y = (float)((r[i][1] - u[1])/uh);
        clip[i].width = (float)(tw/uw); clip[i].height = (float)(th/uh);
    }
    *source = src[0];
    *size = rbl__v2((float)(uw*k), (float)(uh*k));
    *origin = rbl__v2((float)(-u[0]*k), (float)(u[3]*k));
    *flags = f[0]->flags & RBL_FRAME_ROTATED;
    fade->source = src[1];
    fade->weight = weight;
    fade->flags = f[1]->flags & RBL_FRAME_ROTATED;
    fade->clip[0] = clip[0];
    fade->clip[1] = clip[1];
    return true;
}

bool RblAtlasBillboardFade(const RblAtlas *atlas, int frame, int nextFrame, float weight, float worldScale, RblBillboard *billboard, RblFade *fade)
{
    if ((billboard == NULL) || (fade == NULL)) { TraceLog(LOG_WARNING, "RBL: RblAtlasBillboardFade: NULL billboard or fade"); return false; }
    Rectangle src; Vector2 size, origin; unsigned int flags; RblFade f;
    if (!rbl__atlasFadeQuad(atlas, frame, nextFrame, weight, worldScale, "RblAtlasBillboardFade", &src, &size, &origin, &flags, &f)) return false;
    billboard->source = src; billboard->size = size; billboard->origin = origin;
    billboard->flags = (billboard->flags & ~RBL__FRAME_BITS) | flags;
    *fade = f;
    return true;
}

bool RblAtlasInstanceFade(const RblAtlas *atlas, int frame, int nextFrame, float weight, float worldScale, RblInstance *instance, RblFade *fade)
{
    if ((instance == NULL) || (fade == NULL)) { TraceLog(LOG_WARNING, "RBL: RblAtlasInstanceFade: NULL instance or fade"); return false; }
    Rectangle src; Vector2 size, origin; unsigned int flags; RblFade f;
    if (!rbl__atlasFadeQuad(atlas, frame, nextFrame, weight, worldScale, "RblAtlasInstanceFade", &src, &size, &origin, &flags, &f)) return false;
    instance->source = src; instance->size = size; instance->origin = origin;
    instance->flags = (instance->flags & ~RBL__FRAME_BITS) | flags;
    *fade = f;
    return true;
}

// ---- slices: sub-frames of a frame -------------------------------------------------------------
int RblAtlasFindSlice(const RblAtlas *atlas, const char *name, int frame)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblAtlasFindSlice");
    if (s == NULL) return -1;
    if (name == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasFindSlice: NULL name"); return -1; }
    if ((frame < 0) || (frame >= s->frameCount)) { TraceLog(LOG_WARNING, "RBL: RblAtlasFindSlice: frame %i outside 0..%i", frame, s->frameCount - 1); return -1; }
    for (int i = 0; i < s->sliceCount; i++)
        if ((s->slices[i].frame <= frame) && (frame <= s->slices[i].lastFrame) && (strcmp(s->slices[i].name, name) == 0)) return i;
    return -1;
}

// A slice key drawn alone at a frame it applies to: its bounds clipped to the frame's trim (only
// drawn pixels are sampled), placed about its pivot as a frame about its own
static bool rbl__atlasSliceQuad(const RblAtlas *atlas, int slice, int frame, float worldScale, const char *fn, Rectangle *source, Vector2 *size, Vector2 *origin, unsigned int *flags)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, fn);
    if (s == NULL) return false;
    if ((frame < 0) || (frame >= s->frameCount)) { TraceLog(LOG_WARNING, "RBL: %s: frame %i outside 0..%i", fn, frame, s->frameCount - 1); return false; }
    if ((slice < 0) || (slice >= s->sliceCount)) { TraceLog(LOG_WARNING, "RBL: %s: slice %i outside 0..%i", fn, slice, s->sliceCount - 1); return false; }
    const RblAtlasSlice *key = &s->slices[slice];
    if ((frame < key->frame) || (frame > key->lastFrame)) { TraceLog(LOG_WARNING, "RBL: %s: slice key %i applies to frames %i..%i, not %i (RblAtlasFindSlice)", fn, slice, key->frame, key->lastFrame, frame); return false; }
    if (!rbl__finite(worldScale) || !(worldScale > 0.0f) || (worldScale > 1e15f)) { TraceLog(LOG_WARNING, "RBL: %s: worldScale must be finite and in (0, 1e15]", fn); return false; }
    const RblAtlasFrame *f = &s->frames[frame];
    const Rectangle t = f->trim, b = key->bounds;
    double l = fmax(b.x, t.x), top = fmax(b.y, t.y), r = fmin((double)b.x + b.width, (double)t.x + t.width), bottom = fmin((double)b.y + b.height, (double)t.y + t.height);
    if (!((r > l) && (bottom > top))) { TraceLog(LOG_WARNING, "RBL: %s: slice \"%s\" lies outside frame %i's drawn (trimmed) pixels", fn, key->name, frame); return false; }
    double k = rbl__atlasUnit(s, f, worldScale);
    *source = rbl__atlasSubSource(f, (l - t.x)/t.width, (r - t.x)/t.width, (top - t.y)/t.height, (bottom - t.y)/t.height);
    *size = rbl__v2((float)((r - l)*k), (float)((bottom - top)*k));
    *origin = rbl__v2((float)((key->pivot.x - l)*k), (float)((bottom - key->pivot.y)*k));
    *flags = f->flags & RBL_FRAME_ROTATED;
    return true;
}

bool RblAtlasSliceBillboard(const RblAtlas *atlas, int slice, int frame, float worldScale, RblBillboard *billboard)
{
    if (billboard == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasSliceBillboard: NULL billboard"); return false; }
    Rectangle src; Vector2 size, origin; unsigned int flags;
    if (!rbl__atlasSliceQuad(atlas, slice, frame, worldScale, "RblAtlasSliceBillboard", &src, &size, &origin, &flags)) return false;
    billboard->source = src; billboard->size = size; billboard->origin = origin;
    billboard->flags = (billboard->flags & ~RBL__FRAME_BITS) | flags;
    return true;
}

bool RblAtlasSliceInstance(const RblAtlas *atlas, int slice, int frame, float worldScale, RblInstance *instance)
{
    if (instance == NULL) { TraceLog(LOG_WARNING, "RBL: RblAtlasSliceInstance: NULL instance"); return false; }
    Rectangle src; Vector2 size, origin; unsigned int flags;
    if (!rbl__atlasSliceQuad(atlas, slice, frame, worldScale, "RblAtlasSliceInstance", &src, &size, &origin, &flags)) return false;
    instance->source = src; instance->size = size; instance->origin = origin;
    instance->flags = (instance->flags & ~RBL__FRAME_BITS) | flags;
    return true;
}

// ---- a page's textures into a Material ----------------------------------------------------------
// The colour sheet into ALBEDO and, when there is one, its same-layout normal sheet into NORMAL
// (an RGB tangent-space map: RblMaterialLayout.normalEncoding RGB), both checked before either slot
// changes; the slots' previous textures are replaced, not unloaded (UnloadMaterial frees these)
bool RblLoadAtlasTextures(const RblAtlas *atlas, int page, const char *normalSuffix, Material *material, RblMaterialLayout *layout)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblLoadAtlasTextures");
    if (s == NULL) return false;
    if ((page < 0) || (page >= s->pageCount)) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlasTextures: page %i outside 0..%i", page, s->pageCount - 1); return false; }
    if ((material == NULL) || (material->maps == NULL)) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlasTextures: NULL material or material.maps"); return false; }
    const RblAtlasPage *pg = &s->pages[page];
    char suffixed[RBL__ATLAS_PATH];
    const char *normalPath = pg->normalImage;          // NULL suffix: the file's pairing or "_n" found at load
    if (normalSuffix != NULL)
    {
        normalPath = NULL;                              // "": no normal sheet
        if ((normalSuffix[0] != 0) && !rbl__pathWithSuffix(pg->image, normalSuffix, suffixed, sizeof(suffixed))) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlasTextures: normal sheet path longer than %i bytes", RBL__ATLAS_PATH - 1); return false; }
        if (normalSuffix[0] != 0) normalPath = suffixed;
    }
    const char *missing = ((pg->image[0] == 0) || !FileExists(pg->image))? pg->image : (((normalPath != NULL) && !FileExists(normalPath))? normalPath : NULL);
    if (missing != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadAtlasTextures: %s \"%s\" not found", (missing == pg->image)? "sheet" : "normal sheet", missing); return false; }
    Texture2D albedo = LoadTexture(pg->image), normal;
    memset(&normal, 0, sizeof(normal));
    if ((albedo.id != 0) && (normalPath != NULL)) normal = LoadTexture(normalPath);
    const char *bad = (albedo.id == 0)? "the sheet did not load (no GL context, or not an image)" : (((normalPath != NULL) && (normal.id == 0))? "the normal sheet did not load" : NULL);
    if ((bad == NULL) && (pg->width > 0) && ((albedo.width != pg->width) || (albedo.height != pg->height))) bad = "the sheet's size differs from the size the atlas states";
    if ((bad == NULL) && (normal.id != 0) && ((normal.width != albedo.width) || (normal.height != albedo.height))) bad = "the normal sheet's size differs from the sheet's (same layout needed)";
    if (bad != NULL)
    {
        if (albedo.id != 0) UnloadTexture(albedo);
        if (normal.id != 0) UnloadTexture(normal);
        TraceLog(LOG_WARNING, "RBL: RblLoadAtlasTextures: \"%s\": %s", pg->image, bad);
        return false;
    }
    // ES 2 / WebGL1 sample a non-power-of-two texture only with clamped edges
    const bool npot = ((albedo.width & (albedo.width - 1)) != 0) || ((albedo.height & (albedo.height - 1)) != 0);
    if ((rbl__glsl() == 100) && npot) { SetTextureWrap(albedo, TEXTURE_WRAP_CLAMP); if (normal.id != 0) SetTextureWrap(normal, TEXTURE_WRAP_CLAMP); }
    material->maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    if (normal.id != 0) material->maps[MATERIAL_MAP_NORMAL].texture = normal;
    if (layout != NULL)
    {
        memset(layout, 0, sizeof(*layout));
        layout->normalEncoding = (normal.id != 0)? RBL_NORMAL_RGB : RBL_NORMAL_NONE;
        layout->premultipliedAlpha = pg->premultiplied;
    }
    return true;
}

// ---- animation ------------------------------------------------------------------------------
static void rbl__spriteRange(const rbl__AtlasState *s, int tag, int *from, int *to, int *direction, int *repeat)
{
    if (tag < 0) { *from = 0; *to = s->frameCount - 1; *direction = RBL_SPRITE_FORWARD; *repeat = 0; return; }
    *from = s->tags[tag].from; *to = s->tags[tag].to; *direction = s->tags[tag].direction; *repeat = s->tags[tag].repeat;
}

static double rbl__spriteDuration(const rbl__AtlasState *s, int frame)
{
    float d = s->frames[frame].duration;
    return (d > 0.0f)? (double)d : (double)RBL_SPRITE_DEFAULT_FRAME_TIME;
}

RblSpritePlayer RblPlaySprite(const RblAtlas *atlas, int tag, int loops)
{
    RblSpritePlayer p;
    memset(&p, 0, sizeof(p));
    p.tag = -1; p.step = 1;
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblPlaySprite");
    if (s == NULL) return p;
    if ((tag < -1) || (tag >= s->tagCount)) { TraceLog(LOG_WARNING, "RBL: RblPlaySprite: tag %i outside -1..%i (first frame shown)", tag, s->tagCount - 1); return p; }
    if (loops < -1) { TraceLog(LOG_WARNING, "RBL: RblPlaySprite: loops %i below -1 (first frame shown)", loops); return p; }
    int from, to, dir, repeat;
    rbl__spriteRange(s, tag, &from, &to, &dir, &repeat);
    p.tag = tag;
    p.loops = (loops == 0)? repeat : ((loops < 0)? 0 : loops);
    bool backward = (dir == RBL_SPRITE_REVERSE) || (dir == RBL_SPRITE_PINGPONG_REVERSE);
    p.frame = backward? to : from;
    p.step = backward? -1 : 1;
    return p;
}

// One frame on: false when the last pass ended (the player stays on its frame, finished)
static bool rbl__spriteAdvance(RblSpritePlayer *p, int from, int to, int dir)
{
    int next = p->frame + p->step;
    if ((next >= from) && (next <= to)) { p->frame = next; return true; }
    p->passes++;
    if ((p->loops > 0) && (p->passes >= p->loops)) { p->finished = true; return false; }
    if ((dir == RBL_SPRITE_PINGPONG) || (dir == RBL_SPRITE_PINGPONG_REVERSE))
    {
        p->step = -p->step;
        if (from < to) p->frame += p->step;     // the turn frame shows once
    }
    else p->frame = (p->step > 0)? from : to;
    return true;
}

// One player advanced by dt (validated by the caller): NULL, or why the player is not one of
// RblPlaySprite's for this atlas (then it is untouched)
static const char *rbl__spriteStep(const rbl__AtlasState *s, RblSpritePlayer *player, float dt)
{
    RblSpritePlayer p = *player;
    int from, to, dir, repeat;
    if ((p.tag < -1) || (p.tag >= s->tagCount)) return "player's tag not in this atlas";
    rbl__spriteRange(s, p.tag, &from, &to, &dir, &repeat);
    bool pingpong = (dir == RBL_SPRITE_PINGPONG) || (dir == RBL_SPRITE_PINGPONG_REVERSE);
    if ((p.frame < from) || (p.frame > to) || ((p.step != 1) && (p.step != -1)) || !rbl__finite(p.time) || (p.time < 0.0f) || (p.loops < 0) || (p.passes < 0))
        return "player state not from RblPlaySprite for this atlas (frame, step, time or counts)";
    if ((double)p.time > rbl__spriteDuration(s, p.frame)) return "player's time is beyond its frame's duration (not a state RblUpdateSprite makes)";
    if (p.finished) return NULL;
    double t = (double)p.time + dt;
    // Most updates stay inside the current frame: no period, no stepping
    if (t < rbl__spriteDuration(s, p.frame)) { player->time = (float)t; if (player->time >= (float)rbl__spriteDuration(s, p.frame)) player->time = nextafterf((float)rbl__spriteDuration(s, p.frame), 0.0f); return NULL; }
    // Whole periods change nothing but the pass count: skip them (a huge dt costs no more than one)
    double period = 0.0;
    for (int i = from; i <= to; i++) period += rbl__spriteDuration(s, i);
    int perPeriod = 1;     // passes per period: a pingpong period is both legs (one frame: each step is a leg)
    if (pingpong && (to > from)) { for (int i = from + 1; i < to; i++) period += rbl__spriteDuration(s, i); perPeriod = 2; }
    if (t > 2.0*period)
    {
        double whole = floor(t/period) - 1.0;
        if (p.loops > 0)
        {
            double room = floor((double)(p.loops - p.passes - 2)/perPeriod);
            if (whole > room) whole = room;
        }
        if (whole > 0.0)
        {
            t -= whole*period;
            double passes = (double)p.passes + whole*perPeriod;
            p.passes = (passes > 2e9)? (int)(fmod(passes, 1e9) + 1e9) : (int)passes;
        }
    }
    for (int guard = 0; guard < 1 << 20; guard++)
    {
        double d = rbl__spriteDuration(s, p.frame);
        if (t < d) break;
        if (!rbl__spriteAdvance(&p, from, to, dir)) { t = 0.0; break; }
        t -= d;
    }
    p.time = (float)t;
    if (p.time >= (float)rbl__spriteDuration(s, p.frame)) p.time = nextafterf((float)rbl__spriteDuration(s, p.frame), 0.0f);
    *player = p;
    return NULL;
}

bool RblUpdateSprite(RblSpritePlayer *player, const RblAtlas *atlas, float dt)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblUpdateSprite");
    if (s == NULL) return false;
    if (player == NULL) { TraceLog(LOG_WARNING, "RBL: RblUpdateSprite: NULL player"); return false; }
    if (!rbl__finite(dt) || (dt < 0.0f)) { TraceLog(LOG_WARNING, "RBL: RblUpdateSprite: dt must be finite and >= 0"); return false; }
    const char *bad = rbl__spriteStep(s, player, dt);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblUpdateSprite: %s", bad); return false; }
    return true;
}

int RblUpdateSpriteInstances(RblSpritePlayer *players, RblInstance *instances, int count, const RblAtlas *atlas, float dt, float worldScale)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblUpdateSpriteInstances");
    if (s == NULL) return 0;
    if ((count < 0) || (count > RBL_MAX_INSTANCES) || ((count > 0) && ((players == NULL) || (instances == NULL))))
    {
        TraceLog(LOG_WARNING, "RBL: RblUpdateSpriteInstances: count %i outside 0..RBL_MAX_INSTANCES (%i), or players/instances NULL", count, RBL_MAX_INSTANCES);
        return 0;
    }
    if (!rbl__finite(dt) || (dt < 0.0f)) { TraceLog(LOG_WARNING, "RBL: RblUpdateSpriteInstances: dt must be finite and >= 0"); return 0; }
    if (!rbl__finite(worldScale) || !(worldScale > 0.0f) || (worldScale > 1e15f)) { TraceLog(LOG_WARNING, "RBL: RblUpdateSpriteInstances: worldScale must be finite and in (0, 1e15]"); return 0; }
    // the checks above once, then per instance: the step and the frame's fields (as RblAtlasInstance,
    // with each page's world units per texel divided out once)
    double unit[RBL__ATLAS_MAX_PAGES];
    for (int p = 0; p < s->pageCount; p++) unit[p] = (double)worldScale/(double)s->pages[p].scale;
    int done = 0, skipped = 0;
    const char *why = NULL;
    for (int i = 0; i < count; i++)
    {
        const char *bad = rbl__spriteStep(s, &players[i], dt);
        if (bad != NULL) { skipped++; why = bad; continue; }
        RblInstance *in = &instances[i];
        unsigned int flags;
        const RblAtlasFrame *f = &s->frames[players[i].frame];
        rbl__atlasFrameQuad(f, unit[f->page], &in->source, &in->size, &in->origin, &flags);
        in->flags = (in->flags & ~RBL__FRAME_BITS) | flags;
        done++;
    }
    if (skipped > 0) TraceLog(LOG_WARNING, "RBL: RblUpdateSpriteInstances: %i players skipped (instances untouched): %s", skipped, why);
    return done;
}

// The frame after the player's and the weight time/duration (0 and its own frame when finished);
// NULL, or why the player is not one of RblPlaySprite's for this atlas
static const char *rbl__spriteBlend(const rbl__AtlasState *s, const RblSpritePlayer *player, int *nextFrame, float *weight)
{
    int from, to, dir, repeat;
    if ((player->tag < -1) || (player->tag >= s->tagCount)) return "player's tag not in this atlas";
    rbl__spriteRange(s, player->tag, &from, &to, &dir, &repeat);
    if ((player->frame < from) || (player->frame > to) || ((player->step != 1) && (player->step != -1)) || !rbl__finite(player->time) || (player->time < 0.0f) || (player->loops < 0) || (player->passes < 0))
        return "player state not from RblPlaySprite for this atlas";
    // RblUpdateSprite keeps time inside the frame; more is not a state it makes
    if ((double)player->time > rbl__spriteDuration(s, player->frame)) return "player's time is beyond its frame's duration (not a state RblUpdateSprite makes)";
    RblSpritePlayer p = *player;
    *nextFrame = p.frame;
    *weight = 0.0f;
    if (p.finished) return NULL;
    double w = (double)p.time/rbl__spriteDuration(s, p.frame);
    if (!rbl__spriteAdvance(&p, from, to, dir)) return NULL;
    *nextFrame = p.frame;
    *weight = (float)((w < 0.0)? 0.0 : ((w > 1.0)? 1.0 : w));
    return NULL;
}

float RblSpriteBlend(const RblSpritePlayer *player, const RblAtlas *atlas, int *nextFrame)
{
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblSpriteBlend");
    if (s == NULL) return 0.0f;
    if ((player == NULL) || (nextFrame == NULL)) { TraceLog(LOG_WARNING, "RBL: RblSpriteBlend: NULL player or nextFrame"); return 0.0f; }
    int next;
    float w;
    const char *bad = rbl__spriteBlend(s, player, &next, &w);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblSpriteBlend: %s", bad); return 0.0f; }
    *nextFrame = next;
    return w;
}

int RblSpriteViewSector(Vector3 viewDirection, float facingDegrees, int directions)
{
    if ((directions < 1) || (directions > 360)) { TraceLog(LOG_WARNING, "RBL: RblSpriteViewSector: directions %i outside 1..360", directions); return -1; }
    if (!rbl__finite(viewDirection.x) || !rbl__finite(viewDirection.y) || !rbl__finite(viewDirection.z) || !rbl__finite(facingDegrees) || (fabsf(facingDegrees) > 1e9f))
    { TraceLog(LOG_WARNING, "RBL: RblSpriteViewSector: NaN/Inf view direction or facing (|facing| <= 1e9)"); return -1; }
    // The eye seen from the sprite, on the ground plane: angle about +Y from +Z (the facing's 0)
    double ex = -(double)viewDirection.x, ez = -(double)viewDirection.z;
    if ((ex == 0.0) && (ez == 0.0) && (viewDirection.y == 0.0f)) { TraceLog(LOG_WARNING, "RBL: RblSpriteViewSector: zero view direction"); return -1; }
    if ((ex == 0.0) && (ez == 0.0)) return 0;        // straight down or up: the front
    double eye = atan2(ex, ez)*(180.0/3.14159265358979323846);
    double rel = fmod(eye - fmod((double)facingDegrees, 360.0), 360.0);
    if (rel < 0.0) rel += 360.0;
    double width = 360.0/directions;
    int k = (int)floor((rel + 0.5*width)/width);
    return k % directions;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: resident sprite buffers   >>sprites
//----------------------------------------------------------------------------------
#define RBL__SPRITE_CHUNK 256               // Sprites per culling chunk (bounds kept per chunk)

typedef struct rbl__SpriteBufferState {
    float *pivots;                  // Per sprite: pivot xyz and scale as last written (chunk bounds after a part of a chunk changes)
    float *bounds;                  // Per chunk: pivots' min xyz, max xyz, largest scale (-1: nothing to draw)
    int *runs;                      // Draw scratch: first sprite and count of each visible run of chunks
    int capacity, count, chunks;
    int frameCount, tagCount;       // Of the atlas the table was built from (what updates are checked against)
    float radius;                   // Farthest quad corner from the pivot over every frame, per unit of scale
    int tableWidth;
    int corners;                    // Most corners of a polygon frame (0: the atlas has none, quads only)
    unsigned int vaoId, vboId, tableId;
    // The second store a whole-buffer update writes, checking as it goes, and swaps in on success
    // (made on the first such update)
    unsigned int spareVaoId, spareVboId;
    float *sparePivots, *spareBounds;
} rbl__SpriteBufferState;

// The resident-sprite variant of an instanced program (lit, G-buffer or caster)
static rbl__Program *rbl__spriteVariant(rbl__Program *p) { return rbl__ownVariant(p, &p->spriteVariant, 1); }

static rbl__SpriteBufferState *rbl__spriteState(const RblSpriteBuffer *buffer)
{
    return ((buffer != NULL) && rbl__isLive(buffer->id, buffer->state))? buffer->state : NULL;
}

static void rbl__freeSpriteState(rbl__SpriteBufferState *b)
{
    if (!rbl__glUsable()) b->vaoId = b->vboId = b->tableId = b->spareVaoId = b->spareVboId = 0;      // gone with the context
    if (b->vaoId != 0) rlUnloadVertexArray(b->vaoId);
    if (b->vboId != 0) rlUnloadVertexBuffer(b->vboId);
    if (b->spareVaoId != 0) rlUnloadVertexArray(b->spareVaoId);
    if (b->spareVboId != 0) rlUnloadVertexBuffer(b->spareVboId);
    if (b->tableId != 0) rlUnloadTexture(b->tableId);
    RBL_FREE(b->pivots);
    RBL_FREE(b->bounds);
    RBL_FREE(b->sparePivots);
    RBL_FREE(b->spareBounds);
    RBL_FREE(b->runs);
    RBL_FREE(b);
}

// One pass's frames in play order and the period's timeline: forward from..to, reverse to..from,
// pingpong from..to then to-1..from+1 (reverse: to..from, from+1..to-1); RblUpdateSprite's order
static int rbl__spriteTimeline(int from, int to, int dir, int *out)
{
    int n = 0;
    bool reverse = (dir == RBL_SPRITE_REVERSE) || (dir == RBL_SPRITE_PINGPONG_REVERSE);
    bool pingpong = ((dir == RBL_SPRITE_PINGPONG) || (dir == RBL_SPRITE_PINGPONG_REVERSE)) && (to > from);
    for (int i = 0; i <= to - from; i++) { if (out != NULL) out[n] = reverse? to - i : from + i; n++; }
    if (pingpong) for (int i = 1; i < to - from; i++) { if (out != NULL) out[n] = reverse? from + i : to - i; n++; }
    return n;
}

// The frame table of lit_instanced.vs.glsl (RGBA32F texels, layout documented there); NULL when out
// of memory. *texels: texels used; *radius: farthest quad corner from the pivot per unit of scale;
// *corners: the most corners of a polygon frame (0: none)
static float *rbl__buildFrameTable(const rbl__AtlasState *s, int *texels, float *radius, int *corners)
{
    *corners = 0;
    int entries = 0;
    for (int t = -1; t < s->tagCount; t++)
    {
        int from, to, dir, repeat;
        rbl__spriteRange(s, t, &from, &to, &dir, &repeat);
        entries += rbl__spriteTimeline(from, to, dir, NULL);
    }
    int base = 3*s->frameCount, entryBase = base + 2*(s->tagCount + 1);
    int n = entryBase + entries, polygonBase = n;
    for (int k = 0; k < s->frameCount; k++)
    {
        const rbl__Polygon *poly = (s->frames[k].polygon != NULL)? &s->polyDraw[s->frames[k].polygon - s->polygons] : NULL;
        if (poly != NULL) n += 2 + (int)rbl__polygonTexels(poly);     // its header (each cut's first texel and count), its corners
    }
    float *table = (float *)RBL_CALLOC((size_t)n*4, sizeof(float));
    int *order = (int *)RBL_MALLOC((size_t)(2*s->frameCount + 2)*sizeof(int));
    if ((table == NULL) || (order == NULL)) { RBL_FREE(table); RBL_FREE(order); return NULL; }
    double far = 0.0;
    for (int k = 0; k < s->frameCount; k++)
    {
        const RblAtlasFrame *f = &s->frames[k];
        Rectangle src; Vector2 size, origin; unsigned int flags;
        rbl__atlasFrameQuad(f, rbl__atlasUnit(s, f, 1.0f), &src, &size, &origin, &flags);
        float *t = table + (size_t)k*12;
        t[0] = src.x; t[1] = src.y; t[2] = src.width; t[3] = src.height;
        t[4] = size.x; t[5] = size.y; t[6] = origin.x; t[7] = origin.y;
        t[8] = (float)rbl__spriteDuration(s, k); t[9] = (float)(flags & RBL_FRAME_ROTATED);
        if (f->polygon != NULL)
        {
            // A polygon frame: its two header texels (each cut's first corner texel and count, as the
            // polygon table's), then its corners (lit_instanced.vs.glsl's rblPolygonSpan)
            const rbl__Polygon *poly = &s->polyDraw[f->polygon - s->polygons];
            float *h = table + (size_t)polygonBase*4;
            t[10] = (float)polygonBase; t[11] = (float)(1 + rbl__polygonMaxCorners(poly));
            polygonBase += 2;
            for (int d = 0; d < 3; d++)
            {
                h[2*d] = (float)polygonBase; h[2*d + 1] = (float)(3*poly->triangles[d]);
                polygonBase += rbl__polygonCorners(poly, d, table + (size_t)polygonBase*4);
            }
            if (rbl__polygonMaxCorners(poly) > *corners) *corners = rbl__polygonMaxCorners(poly);
        }
        // Either flip mirrors the quad about the pivot: the corner reach is the same
        double x = fmax(fabs((double)origin.x), fabs((double)size.x - origin.x)), y = fmax(fabs((double)origin.y), fabs((double)size.y - origin.y));
        far = fmax(far, sqrt(x*x + y*y));
    }
    int e = entryBase;
    for (int t = -1; t < s->tagCount; t++)
    {
        int from, to, dir, repeat;
        rbl__spriteRange(s, t, &from, &to, &dir, &repeat);
        int count = rbl__spriteTimeline(from, to, dir, order);
        bool pingpong = count > to - from + 1;
        double at = 0.0, firstPass = 0.0;
        for (int i = 0; i < count; i++)
        {
            float *x = table + (size_t)(e + i)*4;
            x[0] = (float)order[i]; x[1] = (float)at;
            at += rbl__spriteDuration(s, order[i]);
            if (i == to - from) firstPass = at;
        }
        bool reverse = (dir == RBL_SPRITE_REVERSE) || (dir == RBL_SPRITE_PINGPONG_REVERSE);
        int odd = reverse? from : to, even = odd;                   // the last frame after an odd / even count of passes
        if (pingpong) even = reverse? to : from;
        float *row = table + (size_t)(base + 2*(t + 1))*4;
        row[0] = (float)e; row[1] = (float)count; row[2] = (float)at; row[3] = (float)firstPass;
        row[4] = (float)odd; row[5] = (float)even; row[6] = (float)((t < 0)? 0 : repeat); row[7] = pingpong? (float)rbl__spriteDuration(s, order[0]) : 0.0f;
        e += count;
    }
    RBL_FREE(order);
    *texels = n;
    *radius = (float)far;
    return table;
}

// The GPU buffer's attributes (lit_instanced.vs.glsl's sprite reading) from sprite first on
#define RBL__SPRITE_ATTRIBUTES 4        // position and scale, start, rotation/frame/tag/speed, tint

static void rbl__spriteAttributes(unsigned int vbo, int first)
{
    const int stride = (int)sizeof(RblSpriteInstance), at = first*stride;
    const unsigned int loc = RBL__INSTANCE_LOCATION;
    rlEnableVertexBuffer(vbo);
    rlSetVertexAttribute(loc + 0, 4, RL_FLOAT, false, stride, at + (int)offsetof(RblSpriteInstance, position));
    rlSetVertexAttribute(loc + 1, 1, RL_FLOAT, false, stride, at + (int)offsetof(RblSpriteInstance, start));
    rlSetVertexAttribute(loc + 2, 4, 0x1403 /* GL_UNSIGNED_SHORT, converted to float */, false, stride, at + (int)offsetof(RblSpriteInstance, rotation));
    rlSetVertexAttribute(loc + 3, 4, RL_UNSIGNED_BYTE, true, stride, at + (int)offsetof(RblSpriteInstance, tint));
}

// A vertex array over a new GPU store of capacity sprites (data: its contents, or NULL)
static void rbl__loadSpriteStore(int capacity, const void *data, unsigned int *vao, unsigned int *vbo)
{
    *vao = rlLoadVertexArray();
    rlEnableVertexArray(*vao);
    *vbo = rlLoadVertexBuffer(data, capacity*(int)sizeof(RblSpriteInstance), true);
    rbl__spriteAttributes(*vbo, 0);
    for (unsigned int i = 0; i < RBL__SPRITE_ATTRIBUTES; i++) { rlEnableVertexAttribute(RBL__INSTANCE_LOCATION + i); rlSetVertexAttributeDivisor(RBL__INSTANCE_LOCATION + i, 1); }
    rlDisableVertexArray();
}

RblSpriteBuffer RblLoadSpriteBuffer(const RblAtlas *atlas, int capacity)
{
    RblSpriteBuffer buffer;
    memset(&buffer, 0, sizeof(buffer));
    const rbl__AtlasState *s = rbl__atlasArg(atlas, "RblLoadSpriteBuffer");
    if (s == NULL) return buffer;
    if ((capacity < 0) || (capacity > RBL_MAX_INSTANCES)) { TraceLog(LOG_WARNING, "RBL: RblLoadSpriteBuffer: capacity %i outside 0..%i", capacity, RBL_MAX_INSTANCES); return buffer; }
    if (rbl__needsGlsl3("sprite buffers") != NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadSpriteBuffer: %s", rbl__state.problem); return buffer; }
    if (capacity == 0) capacity = RBL_BATCH_DEFAULT_CAPACITY;
    int texels = 0, corners = 0;
    float radius = 0.0f;
    float *table = rbl__buildFrameTable(s, &texels, &radius, &corners);
    int rows = (texels + RBL__FRAME_TABLE_WIDTH - 1)/RBL__FRAME_TABLE_WIDTH;
    if ((table != NULL) && (rows > 2048)) { RBL_FREE(table); TraceLog(LOG_WARNING, "RBL: RblLoadSpriteBuffer: frame table of %i texels exceeds 1024 x 2048", texels); return buffer; }
    int chunks = (capacity + RBL__SPRITE_CHUNK - 1)/RBL__SPRITE_CHUNK;
    rbl__SpriteBufferState *b = (rbl__SpriteBufferState *)RBL_CALLOC(1, sizeof(rbl__SpriteBufferState));
    if (b != NULL)
    {
        b->pivots = (float *)RBL_CALLOC((size_t)capacity*4, sizeof(float));
        b->bounds = (float *)RBL_MALLOC((size_t)chunks*7*sizeof(float));
        b->runs = (int *)RBL_MALLOC((size_t)chunks*2*sizeof(int));
    }
    float *padded = (table != NULL)? (float *)RBL_CALLOC((size_t)rows*RBL__FRAME_TABLE_WIDTH*4, sizeof(float)) : NULL;
    void *zeros = RBL_CALLOC((size_t)capacity, sizeof(RblSpriteInstance));        // hidden sprites until written
    if ((b == NULL) || (b->pivots == NULL) || (b->bounds == NULL) || (b->runs == NULL) || (padded == NULL) || (zeros == NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadSpriteBuffer: out of memory for %i sprites", capacity);
        if (b != NULL) { RBL_FREE(b->pivots); RBL_FREE(b->bounds); RBL_FREE(b->runs); RBL_FREE(b); }
        RBL_FREE(table); RBL_FREE(padded); RBL_FREE(zeros);
        return buffer;
    }
    for (int c = 0; c < chunks; c++) b->bounds[c*7 + 6] = -1.0f;
    memcpy(padded, table, (size_t)texels*4*sizeof(float));
    RBL_FREE(table);
    b->capacity = capacity; b->chunks = chunks; b->radius = radius;
    b->frameCount = s->frameCount; b->tagCount = s->tagCount; b->tableWidth = RBL__FRAME_TABLE_WIDTH;
    b->corners = corners;
    b->tableId = rlLoadTexture(padded, RBL__FRAME_TABLE_WIDTH, rows, RL_PIXELFORMAT_UNCOMPRESSED_R32G32B32A32, 1);
    RBL_FREE(padded);
    if (b->tableId != 0)
    {
        // texelFetch only, but a float texture must be complete (no linear filter) to be read on ES 3
        rlTextureParameters(b->tableId, RL_TEXTURE_MIN_FILTER, RL_TEXTURE_FILTER_NEAREST);
        rlTextureParameters(b->tableId, RL_TEXTURE_MAG_FILTER, RL_TEXTURE_FILTER_NEAREST);
    }
    rbl__loadSpriteStore(capacity, zeros, &b->vaoId, &b->vboId);
    RBL_FREE(zeros);
    unsigned int id = ((b->vaoId != 0) && (b->vboId != 0) && (b->tableId != 0))? rbl__liveAdd(b) : 0;
    if (id == 0)
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadSpriteBuffer: GPU buffer or frame table could not be created (no GL context?)");
        rbl__freeSpriteState(b);
        return buffer;
    }
    buffer.capacity = capacity;
    buffer.state = b;
    buffer.id = id;
    return buffer;
}

bool RblIsSpriteBufferValid(RblSpriteBuffer buffer)
{
    return rbl__spriteState(&buffer) != NULL;
}

void RblUnloadSpriteBuffer(RblSpriteBuffer *buffer)
{
    if (!rbl__unloadable(buffer, (buffer != NULL)? buffer->id : 0, (buffer != NULL)? buffer->state : NULL, "RblUnloadSpriteBuffer", "sprite buffer")) { if (buffer != NULL) memset(buffer, 0, sizeof(*buffer)); return; }
    rbl__liveRemove(buffer->id);
    rbl__freeSpriteState(buffer->state);
    memset(buffer, 0, sizeof(*buffer));
    rbl__tidyAfterClose();
}

// Half-float bits of a finite value in [0, 65504], rounded to nearest (ties away); 0xFFFF when it does not fit
static unsigned short rbl__halfBits(float value)
{
    double v = value;
    if (!(v >= 0.0) || !(v <= 65504.0)) return 0xFFFF;
    if (v < 6.103515625e-05)
    {
        double m = floor(v*16777216.0 + 0.5);                       // subnormal: units of 2^-24 (1024 is the least normal)
        return (unsigned short)m;
    }
    int e = 0;
    double mant = frexp(v, &e);                                     // v = mant 2^e, mant in [0.5, 1)
    double m = floor((mant*2.0 - 1.0)*1024.0 + 0.5);
    e -= 1;
    if (m >= 1024.0) { m = 0.0; e++; }
    if (e + 15 >= 31) return 0xFFFF;
    return (unsigned short)(((unsigned int)(e + 15) << 10) | (unsigned int)m);
}

RblSpriteInstance RblMakeSprite(Vector3 position, float scale, float rotation, int frame, Color tint)
{
    RblSpriteInstance sprite;
    memset(&sprite, 0, sizeof(sprite));
    if (!rbl__exponentsBelow(&position, 3, RBL__INSTANCE_LIMIT_EXPONENT) || !rbl__finite(scale) || (scale < 0.0f) || (scale > 1e15f) ||
        !rbl__finite(rotation) || (frame < 0) || (frame > 65535))
    {
        TraceLog(LOG_WARNING, "RBL: RblMakeSprite: NaN/Inf or |value| >= 2^120 position, scale outside [0, 1e15], NaN/Inf rotation or frame %i outside 0..65535 (hidden sprite returned)", frame);
        return sprite;
    }
    double turns = fmod((double)rotation, 360.0);
    if (turns < 0.0) turns += 360.0;
    sprite.position = position; sprite.scale = scale; sprite.tint = tint;
    sprite.rotation = (unsigned short)((unsigned int)floor(turns*(65536.0/360.0) + 0.5) & 0xFFFFu);
    sprite.frame = (unsigned short)frame;
    return sprite;
}

bool RblAnimateSprite(RblSpriteInstance *sprite, int tag, int loops, float start, float speed)
{
    if (sprite == NULL) { TraceLog(LOG_WARNING, "RBL: RblAnimateSprite: NULL sprite"); return false; }
    unsigned short bits = rbl__halfBits(speed);
    if ((tag < -1) || (tag > 65534) || (loops < -1) || (loops > 254) || !rbl__exponentsBelow(&start, 1, RBL__INSTANCE_LIMIT_EXPONENT) || (bits == 0xFFFF))
    {
        TraceLog(LOG_WARNING, "RBL: RblAnimateSprite: tag %i outside -1..65534, loops %i outside -1..254, NaN/Inf start or speed outside [0, 65504]", tag, loops);
        return false;
    }
    sprite->frame = (unsigned short)((tag < 0)? 0xFFFF : tag);
    sprite->start = start;
    sprite->speed = bits;
    unsigned int l = (loops < 0)? 255u : (unsigned int)loops;
    sprite->mode = (unsigned short)((sprite->mode & 7u) | RBL_SPRITE_ANIMATED | (l << 8));
    return true;
}

// NULL, or why a sprite cannot be drawn by a buffer of this atlas
static const char *rbl__spriteProblem(const rbl__SpriteBufferState *b, const RblSpriteInstance *p)
{
    if (!rbl__exponentsBelow(&p->position, 3, RBL__INSTANCE_LIMIT_EXPONENT)) return "NaN/Inf or |value| >= 2^120 position";
    if (!rbl__finite(p->scale) || (p->scale < 0.0f) || (p->scale > 1e15f)) return "scale outside [0, 1e15]";
    if (!rbl__exponentsBelow(&p->start, 1, RBL__INSTANCE_LIMIT_EXPONENT)) return "NaN/Inf or |value| >= 2^120 start";
    if (((p->speed >> 10) & 31u) == 31u) return "speed is a half-float Inf/NaN";
    if ((p->speed & 0x8000u) != 0u) return "negative speed";
    if ((p->mode & 0xF0u) != 0u) return "unknown mode bits (4..7)";
    if ((p->mode & RBL_SPRITE_ANIMATED) != 0u) { if ((p->frame != 0xFFFF) && (p->frame >= b->tagCount)) return "tag not in the buffer's atlas"; }
    else if (p->frame >= b->frameCount) return "frame not in the buffer's atlas";
    return NULL;
}

// rbl__spriteProblem(b, p) == NULL, without its branches (an update checks every sprite first)
static inline bool rbl__spriteOk(const rbl__SpriteBufferState *b, const RblSpriteInstance *p)
{
    const bool animated = (p->mode & RBL_SPRITE_ANIMATED) != 0u;
    unsigned int ok = (unsigned int)rbl__exponentsBelow(&p->position, 3, RBL__INSTANCE_LIMIT_EXPONENT);
    ok &= (unsigned int)rbl__exponentsBelow(&p->start, 1, RBL__INSTANCE_LIMIT_EXPONENT);
    ok &= (unsigned int)(p->scale >= 0.0f) & (unsigned int)(p->scale <= 1e15f);
    ok &= (unsigned int)(((p->speed >> 10) & 31u) != 31u) & (unsigned int)((p->speed & 0x8000u) == 0u) & (unsigned int)((p->mode & 0xF0u) == 0u);
    ok &= animated? ((unsigned int)(p->frame == 0xFFFF) | (unsigned int)(p->frame < b->tagCount)) : (unsigned int)(p->frame < b->frameCount);
    return ok != 0u;
}

// What an update checks of each sprite (rbl__spriteOk), as lane constants where SSE2 is
typedef struct rbl__SpriteChecks {
#if defined(RBL__SSE2)
    __m128i firstMask, firstBias, secondMask, secondBias;
#endif
    unsigned int frames, tags;
} rbl__SpriteChecks;

static rbl__SpriteChecks rbl__spriteChecks(const rbl__SpriteBufferState *b)
{
    rbl__SpriteChecks k;
    memset(&k, 0, sizeof(k));
    k.frames = (unsigned int)b->frameCount; k.tags = (unsigned int)b->tagCount;
#if defined(RBL__SSE2)
    // First half: position xyz (exponent fields) and scale (magnitude at most 1e15's; its sign
    // apart, as -0 passes). Second half, lanes moved to: start (exponent), speed | mode << 16 twice
    // (speed's sign and mode bits 4..7; speed's exponent field all ones)
    const int bias = (int)((256u - RBL__INSTANCE_LIMIT_EXPONENT) << 23);
    const float most = 1e15f;
    int mostBits;
    memcpy(&mostBits, &most, sizeof(mostBits));
    k.firstMask = _mm_setr_epi32(0x7f800000, 0x7f800000, 0x7f800000, 0x7FFFFFFF); k.firstBias = _mm_setr_epi32(bias, bias, bias, 0x7FFFFFFF - mostBits);
    k.secondMask = _mm_setr_epi32(0x7f800000, 0x00F08000, 0x7C00, 0); k.secondBias = _mm_setr_epi32(bias, 0x7FFFFFFF, 0x7FFF8400, 0);
#endif
    return k;
}

#if defined(RBL__SSE2)
// One sprite into the running failures: a value past its limit carries into its lane's sign bit
// (bad), a negative scale sets lane 3 of negative; the frame as integers
RBL__FORCE_INLINE void rbl__checkSprite(const rbl__SpriteChecks *k, const RblSpriteInstance *s, __m128i *bad, __m128 *negative, unsigned int *badFrame)
{
    const __m128i *p = (const __m128i *)(const void *)s;
    const __m128i lo = _mm_loadu_si128(p), hi = _mm_shuffle_epi32(_mm_loadu_si128(p + 1), _MM_SHUFFLE(0, 3, 3, 0));
    *bad = _mm_or_si128(*bad, _mm_or_si128(_mm_add_epi32(_mm_and_si128(lo, k->firstMask), k->firstBias), _mm_add_epi32(_mm_and_si128(hi, k->secondMask), k->secondBias)));
    *negative = _mm_or_ps(*negative, _mm_cmplt_ps(_mm_castsi128_ps(lo), _mm_setzero_ps()));
    const unsigned int frame = s->frame, animated = (unsigned int)((s->mode & RBL_SPRITE_ANIMATED) != 0u);
    *badFrame |= (unsigned int)(frame >= (animated? k->tags : k->frames)) & ~(animated & (unsigned int)(frame == 0xFFFFu));
}

static inline bool rbl__checksPassed(__m128i bad, __m128 negative, unsigned int badFrame)
{
    return ((_mm_movemask_ps(_mm_castsi128_ps(bad)) | (_mm_movemask_ps(negative) & 8)) == 0) && (badFrame == 0u);
}
#endif

// Every one of count sprites passes rbl__spriteOk (four lanes a sprite where SSE2 is)
static bool rbl__spritesOk(const rbl__SpriteBufferState *b, const RblSpriteInstance *sprites, int count)
{
#if defined(RBL__SSE2)
    const rbl__SpriteChecks k = rbl__spriteChecks(b);
    __m128i bad = _mm_setzero_si128();
    __m128 negative = _mm_setzero_ps();
    unsigned int badFrame = 0u;
    for (int i = 0; i < count; i++) rbl__checkSprite(&k, &sprites[i], &bad, &negative, &badFrame);
    return rbl__checksPassed(bad, negative, badFrame);
#else
    unsigned int ok = 1u;
    for (int i = 0; i < count; i++) ok &= (unsigned int)rbl__spriteOk(b, &sprites[i]);
    return ok != 0u;
#endif
}

// Chunk c's pivot bounds and largest scale (into bounds) from the pivots of count sprites, one
// sprite at a time (+0 for -0)
static inline void rbl__spriteChunkBoundsScalar(const float *pivots, float *bounds, int count, int c)
{
    float *o = bounds + (size_t)c*7;
    o[6] = -1.0f;
    int end = (c + 1)*RBL__SPRITE_CHUNK;
    if (end > count) end = count;
    for (int i = c*RBL__SPRITE_CHUNK; i < end; i++)
    {
        const float *v = pivots + (size_t)i*4;
        if (v[3] == 0.0f) continue;                     // hidden
        if (o[6] < 0.0f) { for (int k = 0; k < 3; k++) o[k] = o[3 + k] = v[k]; o[6] = v[3]; continue; }
        for (int k = 0; k < 3; k++) { if (v[k] < o[k]) o[k] = v[k]; if (v[k] > o[3 + k]) o[3 + k] = v[k]; }
        if (v[3] > o[6]) o[6] = v[3];
    }
    for (int k = 0; (o[6] >= 0.0f) && (k < 6); k++) o[k] += 0.0f;
}

#if defined(RBL__SSE2)
// One pivot | scale lane set into the running bounds; a hidden sprite (scale 0) becomes all NaN
// lanes, which min/max pass over (they return their second operand when one is NaN)
static inline void rbl__boundsLanes(__m128 v, __m128 *lo, __m128 *hi)
{
    const __m128 w = _mm_or_ps(v, _mm_cmpeq_ps(_mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 3, 3, 3)), _mm_setzero_ps()));
    *lo = _mm_min_ps(w, *lo);
    *hi = _mm_max_ps(w, *hi);
}

// Chunk bounds from two sets of lanes: nothing visible when the largest scale is not above 0; +0
// for -0 (two sets meet zeros of either sign in either order)
static inline void rbl__storeBoundsLanes(float *o, __m128 lo, __m128 hi, __m128 lo2, __m128 hi2)
{
    float l[4], h[4];
    _mm_storeu_ps(l, _mm_add_ps(_mm_min_ps(lo, lo2), _mm_setzero_ps()));
    _mm_storeu_ps(h, _mm_add_ps(_mm_max_ps(hi, hi2), _mm_setzero_ps()));
    if (!(h[3] > 0.0f)) { o[6] = -1.0f; return; }
    for (int k = 0; k < 3; k++) { o[k] = l[k]; o[3 + k] = h[k]; }
    o[6] = h[3];
}
#endif

// Chunk c's pivot bounds and largest scale, as rbl__spriteChunkBoundsScalar's, four lanes at once
// where SSE2 is (min/max round nothing; zeros come out +0 either way)
static void rbl__spriteChunkBounds(const float *pivots, float *bounds, int count, int c)
{
#if defined(RBL__SSE2)
    int end = (c + 1)*RBL__SPRITE_CHUNK;
    if (end > count) end = count;
    __m128 lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY), lo2 = lo, hi2 = hi;
    int i = c*RBL__SPRITE_CHUNK;
    for (; i + 1 < end; i += 2)
    {
        rbl__boundsLanes(_mm_loadu_ps(pivots + (size_t)i*4), &lo, &hi);
        rbl__boundsLanes(_mm_loadu_ps(pivots + (size_t)i*4 + 4), &lo2, &hi2);
    }
    if (i < end) rbl__boundsLanes(_mm_loadu_ps(pivots + (size_t)i*4), &lo, &hi);
    rbl__storeBoundsLanes(bounds + (size_t)c*7, lo, hi, lo2, hi2);
#else
    rbl__spriteChunkBoundsScalar(pivots, bounds, count, c);
#endif
}

// Sprites [from, to) of chunk c from src (sprite from's): into gpu (the mapped slot of sprite from;
// NULL: uploaded apart) and pivots, then the chunk's bounds (of total sprites; from the lanes when
// the chunk is written whole, else from pivots). checks: checked as they go (false: one failed);
// NULL: checked before. b: the atlas's counts (checks without SSE2)
static bool rbl__writeSpriteChunk(const rbl__SpriteBufferState *b, float *pivots, float *bounds, int total, int c, int from, int to, const RblSpriteInstance *src, RblSpriteInstance *gpu, const rbl__SpriteChecks *checks)
{
    int end = (c + 1)*RBL__SPRITE_CHUNK;
    if (end > total) end = total;
    const bool whole = (from == c*RBL__SPRITE_CHUNK) && (to == end);
    bool ok = true;
#if defined(RBL__SSE2)
    // Checked before: the library's copy (the widest stores the machine has), then pivots and
    // bounds from the chunk while it is in the cache. Checked as it goes: each sprite stored beside
    // its checks (the stores' misses overlap the checks' work)
    if ((gpu != NULL) && (checks == NULL)) memcpy(gpu, src, (size_t)(to - from)*sizeof(RblSpriteInstance));
    __m128i *store = (checks != NULL)? (__m128i *)(void *)gpu : NULL;
    __m128 lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY), lo2 = lo, hi2 = hi, negative = _mm_setzero_ps();
    __m128i bad = _mm_setzero_si128();
    unsigned int badFrame = 0u;
    __m128 *out = (__m128 *)(void *)(pivots + (size_t)from*4);
    const float *in = (const float *)(const void *)src;
    const int n = to - from;
    int i = 0;
    for (; i + 1 < n; i += 2)
    {
        if (checks != NULL) { rbl__checkSprite(checks, &src[i], &bad, &negative, &badFrame); rbl__checkSprite(checks, &src[i + 1], &bad, &negative, &badFrame); }
        const __m128 a = _mm_loadu_ps(in + 8*i), a2 = _mm_loadu_ps(in + 8*i + 8);
        if (store != NULL)
        {
            _mm_storeu_ps((float *)(store + 2*i), a); _mm_storeu_si128(store + 2*i + 1, _mm_loadu_si128((const __m128i *)(const void *)(in + 8*i + 4)));
            _mm_storeu_ps((float *)(store + 2*i + 2), a2); _mm_storeu_si128(store + 2*i + 3, _mm_loadu_si128((const __m128i *)(const void *)(in + 8*i + 12)));
        }
        _mm_storeu_ps((float *)(out + i), a);
        _mm_storeu_ps((float *)(out + i + 1), a2);
        rbl__boundsLanes(a, &lo, &hi);
        rbl__boundsLanes(a2, &lo2, &hi2);
    }
    if (i < n)
    {
        if (checks != NULL) rbl__checkSprite(checks, &src[i], &bad, &negative, &badFrame);
        const __m128 a = _mm_loadu_ps(in + 8*i);
        if (store != NULL) { _mm_storeu_ps((float *)(store + 2*i), a); _mm_storeu_si128(store + 2*i + 1, _mm_loadu_si128((const __m128i *)(const void *)(in + 8*i + 4))); }
        _mm_storeu_ps((float *)(out + i), a);
        rbl__boundsLanes(a, &lo, &hi);
    }
    (void)b;
    if (checks != NULL) ok = rbl__checksPassed(bad, negative, badFrame);
    if (whole) { rbl__storeBoundsLanes(bounds + (size_t)c*7, lo, hi, lo2, hi2); return ok; }
#else
    if (gpu != NULL) memcpy(gpu, src, (size_t)(to - from)*sizeof(RblSpriteInstance));
    unsigned int passed = 1u;
    for (int i = 0; i < to - from; i++)
    {
        if (checks != NULL) passed &= (unsigned int)rbl__spriteOk(b, &src[i]);
        float *v = pivots + (size_t)(from + i)*4;
        v[0] = src[i].position.x; v[1] = src[i].position.y; v[2] = src[i].position.z; v[3] = src[i].scale;
    }
    ok = passed != 0u;
    (void)whole;
#endif
    rbl__spriteChunkBounds(pivots, bounds, total, c);
    return ok;
}

// The second GPU store, pivot copy and bounds of a whole-buffer update, made on first use; false:
// not made (the update takes the general way)
static bool rbl__spareSpriteStore(rbl__SpriteBufferState *b)
{
    if (b->spareVboId != 0) return true;
    b->sparePivots = (float *)RBL_CALLOC((size_t)b->capacity*4, sizeof(float));
    b->spareBounds = (float *)RBL_MALLOC((size_t)b->chunks*7*sizeof(float));
    if ((b->sparePivots != NULL) && (b->spareBounds != NULL)) rbl__loadSpriteStore(b->capacity, NULL, &b->spareVaoId, &b->spareVboId);
    if ((b->spareVaoId != 0) && (b->spareVboId != 0)) return true;
    if (b->spareVaoId != 0) rlUnloadVertexArray(b->spareVaoId);
    if (b->spareVboId != 0) rlUnloadVertexBuffer(b->spareVboId);
    RBL_FREE(b->sparePivots); RBL_FREE(b->spareBounds);
    b->spareVaoId = b->spareVboId = 0; b->sparePivots = b->spareBounds = NULL;
    return false;
}

bool RblUpdateSprites(RblSpriteBuffer *pub, int first, int count, const RblSpriteInstance *sprites)
{
    rbl__SpriteBufferState *b = rbl__spriteState(pub);
    if (b == NULL) { TraceLog(LOG_WARNING, "RBL: RblUpdateSprites: sprite buffer not loaded"); return false; }
    if ((first < 0) || (count < 0) || (count > b->capacity - first) || ((count > 0) && (sprites == NULL)))
    {
        TraceLog(LOG_WARNING, "RBL: RblUpdateSprites: range first %i count %i outside the capacity %i, or NULL sprites", first, count, b->capacity);
        return false;
    }
    const size_t size = sizeof(RblSpriteInstance);
    // The whole buffer (where the context maps): one pass over the input checks each sprite as it
    // writes it into the second store, its pivots and bounds; swapped in when every one passed (the
    // store drawn from is untouched otherwise, and the general way names the bad sprite)
    if ((count > 0) && (first == 0) && (count == b->capacity) && !RBL__HOOK(spriteNoMap) && rbl__canMap() && rbl__spareSpriteStore(b))
    {
        RblSpriteInstance *gpu = (RblSpriteInstance *)rbl__mapBuffer(b->spareVboId, (size_t)count*size, false);
        if (gpu != NULL)
        {
            const rbl__SpriteChecks checks = rbl__spriteChecks(b);
            bool ok = true;
            for (int c = 0; ok && (c < b->chunks); c++)
            {
                const int from = c*RBL__SPRITE_CHUNK, to = (from + RBL__SPRITE_CHUNK < count)? from + RBL__SPRITE_CHUNK : count;
                ok = rbl__writeSpriteChunk(b, b->sparePivots, b->spareBounds, count, c, from, to, sprites + from, gpu + from, &checks);
            }
            const bool kept = rbl__unmapBuffer(b->spareVboId);
            if (ok)
            {
                if (!kept) rlUpdateVertexBuffer(b->spareVboId, sprites, count*(int)size, 0);
                unsigned int vao = b->vaoId, vbo = b->vboId;
                float *pivots = b->pivots, *bounds = b->bounds;
                b->vaoId = b->spareVaoId; b->vboId = b->spareVboId; b->pivots = b->sparePivots; b->bounds = b->spareBounds;
                b->spareVaoId = vao; b->spareVboId = vbo; b->sparePivots = pivots; b->spareBounds = bounds;
                b->count = count;
                pub->count = b->count;
#if defined(RBL_INSTRUMENTS)
                rbl__state.spriteMapped++;
#endif
                return true;
            }
        }
    }
    // Every sprite checked before anything is written: a bad one leaves the buffer as it was
    const bool ok = rbl__spritesOk(b, sprites, count);
    for (int i = 0; !ok && (i < count); i++)
    {
        const char *bad = rbl__spriteProblem(b, &sprites[i]);
        if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblUpdateSprites: sprite %i: %s (nothing written)", first + i, bad); return false; }
    }
    if (count == 0) return true;
    if (first + count > b->count) b->count = first + count;
    // The pivot copy and bounds in one pass over the input; the range uploaded from the caller's array
    for (int c = first/RBL__SPRITE_CHUNK; c <= (first + count - 1)/RBL__SPRITE_CHUNK; c++)
    {
        const int from = (c*RBL__SPRITE_CHUNK > first)? c*RBL__SPRITE_CHUNK : first, to = ((c + 1)*RBL__SPRITE_CHUNK < first + count)? (c + 1)*RBL__SPRITE_CHUNK : first + count;
        rbl__writeSpriteChunk(b, b->pivots, b->bounds, b->count, c, from, to, sprites + (from - first), NULL, NULL);
    }
    rlUpdateVertexBuffer(b->vboId, sprites, count*(int)size, first*(int)size);
    pub->count = b->count;
    return true;
}

// Runs of chunks whose bounds (pivots grown by reach x their largest scale) meet the clip volume of
// mvp (each plane's farthest box corner inside): into b->runs; returns the run count
static int rbl__visibleSpriteRuns(rbl__SpriteBufferState *b, Matrix m, float reach)
{
    const float planes[6][4] = {
        { m.m3 + m.m0, m.m7 + m.m4, m.m11 + m.m8, m.m15 + m.m12 }, { m.m3 - m.m0, m.m7 - m.m4, m.m11 - m.m8, m.m15 - m.m12 },
        { m.m3 + m.m1, m.m7 + m.m5, m.m11 + m.m9, m.m15 + m.m13 }, { m.m3 - m.m1, m.m7 - m.m5, m.m11 - m.m9, m.m15 - m.m13 },
        { m.m3 + m.m2, m.m7 + m.m6, m.m11 + m.m10, m.m15 + m.m14 }, { m.m3 - m.m2, m.m7 - m.m6, m.m11 - m.m10, m.m15 - m.m14 } };
    int runs = 0, chunks = (b->count + RBL__SPRITE_CHUNK - 1)/RBL__SPRITE_CHUNK;
    bool open = false, cull = rbl__allFinite(planes, 24);      // a degenerate pass (no viewport yet): nothing culled
    for (int c = 0; c < chunks; c++)
    {
        const float *o = b->bounds + (size_t)c*7;
        bool seen = o[6] >= 0.0f;
        if (seen)
        {
            double r = (double)reach*o[6];
            for (int k = 0; cull && (k < 6) && seen; k++)
            {
                const float *p = planes[k];
                double d = p[3];
                for (int a = 0; a < 3; a++) d += (double)p[a]*((p[a] >= 0.0f)? o[3 + a] + r : o[a] - r);
                seen = d >= 0.0;
            }
        }
        if (!seen) { open = false; continue; }
        int end = (c + 1)*RBL__SPRITE_CHUNK;
        if (end > b->count) end = b->count;
        if (open) b->runs[2*(runs - 1) + 1] = end - b->runs[2*(runs - 1)];
        else { b->runs[2*runs] = c*RBL__SPRITE_CHUNK; b->runs[2*runs + 1] = end - c*RBL__SPRITE_CHUNK; runs++; open = true; }
    }
    return runs;
}

int RblDrawSpriteBuffer(RblSpriteBuffer *pub, Camera3D camera, Material material, RblInstancedDesc desc, float time)
{
    rbl__SpriteBufferState *b = rbl__spriteState(pub);
    if (b == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: sprite buffer not loaded"); return 0; }
    if (!rbl__cameraOk(camera)) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: camera with NaN/Inf or huge fields, fovy outside (0, 180) or unknown projection"); return 0; }
    if (!rbl__exponentsBelow(&time, 1, RBL__INSTANCE_LIMIT_EXPONENT)) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: NaN/Inf or |value| >= 2^120 time"); return 0; }
    if ((desc.sort != RBL_SORT_NONE) || (desc.fades != NULL) || !rbl__instancedDescOk(&desc))
    {
        TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: bad RblInstancedDesc (facing %i, sort %i (resident sprites draw in buffer order), fades (the frame table's), NaN/Inf vectors or a CAMERA_PLANE up of length >= 2^30)", desc.facing, desc.sort);
        return 0;
    }
    rbl__Program *checked = NULL;
    const char *bad = rbl__materialProblem(&material, RBL__PATH_INSTANCED, &checked);
    if (bad != NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: %s", bad); return 0; }
    if (b->count == 0) return 0;
    MaterialMap casterMaps[RBL__CASTER_MAPS];
    rbl__Program *program = NULL;
    if (!rbl__prepareDraw(&material, casterMaps, RBL__PATH_INSTANCED, false, false, "RblDrawSpriteBuffer", &program)) return 0;
    // The program's resident-sprite variant (compiled at its first sprite draw): the plain instanced
    // stage pays nothing for reading sprites
    rbl__Program *variant = rbl__spriteVariant(program);
    if (variant == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: resident-sprite variant unavailable (%s)", rbl__state.problem); return 0; }
    // A polygon sheet: the sprite variant's polygon variant, each sprite drawn with the sheet's most
    // corners (cross-fade programs draw quads: the union of two frames)
    int vertices = 6;
    if ((b->corners > 0) && !variant->key.desc.crossFade)
    {
        variant = rbl__polygonVariant(variant);
        if (variant == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: polygon variant unavailable (%s)", rbl__state.problem); return 0; }
        vertices = (b->corners > 6)? b->corners : 6;
    }
    program = variant;
    material.shader = variant->shader;
    if (rbl__state.shadowPass != NULL) rbl__casterDepth(variant);
    else if (variant->key.desc.softParticles) rbl__bindSoftDepth(variant, &material);
    int texW, texH;
    rbl__albedoSize(&material, &texW, &texH);
    if ((texW <= 0) || (texH <= 0)) { TraceLog(LOG_WARNING, "RBL: RblDrawSpriteBuffer: albedo texture size %ix%i", texW, texH); return 0; }

    // Cull by chunk against this pass's clip volume: a caller up longer than 1 stretches the quad up,
    // a shadow pass's AXIS tilt moves it by up to twice its reach
    float reach = b->radius;
    if (desc.facing == RBL_FACING_CAMERA_PLANE) reach *= fmaxf(1.0f, sqrtf(rbl__dot(desc.up, desc.up)));
    if (rbl__state.shadowPass != NULL) reach *= 3.0f;
    reach *= 1.0f + 1e-5f;
    int runs = rbl__visibleSpriteRuns(b, rbl__matMul(rlGetMatrixModelview(), rlGetMatrixProjection()), reach);
    if (runs == 0) return 0;

    RblCameraFrame view = rbl__cameraFrame(camera);
    if (rbl__state.shadowPass != NULL) rbl__shadowPassView(&view);
    float frame[32];
    rbl__instancingFrame(&desc, &view, texW, texH, frame);
    frame[28] = 1.0f; frame[29] = time; frame[30] = (float)b->tableWidth; frame[31] = (float)b->frameCount;
    // Back faces drawn whenever the mode could show one (RblDrawInstanced tests each instance; a
    // resident set is not read per draw): front faces come out the same
    bool cullOff = (rbl__state.shadowPass == NULL) && ((desc.facing == RBL_FACING_FIXED) || ((desc.facing == RBL_FACING_AXIS) && (camera.projection == CAMERA_ORTHOGRAPHIC)) ||
                   ((desc.facing == RBL_FACING_CAMERA_PLANE) && ((desc.up.x != 0.0f) || (desc.up.y != 0.0f) || (desc.up.z != 0.0f))));
    rlDrawRenderBatchActive();
    unsigned int bound = rbl__bindMaterial(&material);
    rbl__applyMaterialValues(program, &material);
    rlSetUniform(program->loc[RBL__U_INSTANCING], frame, SHADER_UNIFORM_VEC4, 8);
    int unit = RBL_FRAME_TABLE_TEXTURE_UNIT;
    rlActiveTextureSlot(unit);
    rlEnableTexture(b->tableId);
    rlSetUniform(program->loc[RBL__U_FRAME_TABLE], &unit, SHADER_UNIFORM_INT, 1);
    if (program->key.sprites & 2)
    {
        const float poly[4] = { (float)vertices, (float)b->tableWidth, 0.0f, 0.0f };
        rlSetUniform(program->loc[RBL__U_POLYGON], poly, SHADER_UNIFORM_VEC4, 1);
    }
    if (cullOff) rlDisableBackfaceCulling();
    rlEnableVertexArray(b->vaoId);
    int drawn = 0;
    for (int r = 0; r < runs; r++)
    {
        rbl__spriteAttributes(b->vboId, b->runs[2*r]);
        rlDrawVertexArrayInstanced(0, vertices, b->runs[2*r + 1]);
        drawn += b->runs[2*r + 1];
    }
    if (b->runs[0] != 0) rbl__spriteAttributes(b->vboId, 0);
    rbl__markDrawn(program);
    rlDisableVertexArray();
    rlDisableVertexBuffer();
    if (cullOff) rlEnableBackfaceCulling();
    rlActiveTextureSlot(unit);
    rlDisableTexture();
    rbl__unbindMaterial(bound);
    return drawn;
}

#endif // RBL_NO_ATLAS

#endif // RBILLBOARD_LIT_IMPLEMENTATION
