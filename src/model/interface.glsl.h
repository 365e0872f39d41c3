// The host/device interface of every compute pass, declared once for GLSL and C++ (in the manner
// of nvpro_core's host/device headers): the binding number of each resource a shader reads or
// writes, the push-constant blocks, the records a pass writes to its storage buffers, and the
// enumerations both sides interpret. The shaders declare their resources with these constants;
// the Vulkan backend builds descriptor-set layouts, pool sizes and descriptor writes from the
// binding tables at the end of this file (C++ only). Sizes are static_assert-ed here, and
// src/vulkan/tests/interface_test.cpp fails if a compiled shader's reflected bindings, push
// constants or record layouts disagree with this file.
//
// Layout rule for the structs: members are grouped into 16-byte rows (a vec4; a vec3 and a
// scalar; four scalars), so that std140, std430 and the C++ layout are one and the same.
#ifndef CLOUDSCAPE_MODEL_INTERFACE_GLSL_H
#define CLOUDSCAPE_MODEL_INTERFACE_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// ---- Enumerations shared by the model, the shaders and the host.

// Where a resolved temporal pixel came from (TemporalPixel.source).
CONST_INT TEMPORAL_SOURCE_MARCHED = 0;     // marched this frame (blended into still history)
CONST_INT TEMPORAL_SOURCE_REPROJECTED = 1; // the previous frame's result, reprojected
CONST_INT TEMPORAL_SOURCE_FALLBACK = 2;    // this frame's marches upsampled (no usable history)

// Phase-function kinds (PhaseFunction.kind, and the lighting.phase key past the parser).
CONST_INT PHASE_ISOTROPIC = 0;
CONST_INT PHASE_HG = 1;        // params.x = g
CONST_INT PHASE_TWO_LOBE = 2;  // params = (g main, g second, weight of second, -)
CONST_INT PHASE_HG_DRAINE = 3; // params = hgDraineParameters(diameter)

// ---- How the image passes are dispatched. Every pass runs square workgroups of
// PASS_WORKGROUP_SIDE^2 invocations. The march dispatches tiles of MARCH_TILE_WORKGROUPS^2
// workgroups, each from a base workgroup that is a multiple of it; within a tile of the
// full-frame march the rows of workgroups are visited interleaved (interleavedRow; why, and the
// shader's side, in src/model/shaders/dispatch_order.glsl). The other passes keep image order.
CONST_INT PASS_WORKGROUP_SIDE = 8;
CONST_INT MARCH_TILE_WORKGROUPS = 32;
CONST_INT DISPATCH_ROW_STRIDE = 8;

// The row of workgroups that the r-th of a dispatch's n rows covers: a bijection of [0, n) that
// visits every DISPATCH_ROW_STRIDE-th row first (0, 8, 16, .., then 1, 9, 17, ..; the first
// n % stride of those groups hold one row more), so that any contiguous share of a dispatch takes
// rows from its whole height.
inline uint interleavedRow(uint r, uint n) {
    uint stride = uint(DISPATCH_ROW_STRIDE);
    uint perGroup = n / stride;
    uint longGroups = n % stride;
    uint inLongGroups = longGroups * (perGroup + 1u);
    if (r < inLongGroups) {
        return (r % (perGroup + 1u)) * stride + r / (perGroup + 1u);
    }
    uint rest = r - inLongGroups;
    return (rest % perGroup) * stride + longGroups + rest / perGroup;
}

// ---- Records the passes write per pixel. Each is whole rows of 16 bytes, so its buffer is also
// a texel buffer of RGBA32F texels, one per row, which is how the shaders read and write the
// per-pixel ones (src/model/shaders/texel_rows.glsl).

// One pixel of a cloud layer: what the march produces and what the temporal history and the
// upsample read. 32 bytes: CLOUD_TEXEL_ROWS texels.
struct CloudTexel {
    vec4 cloud;   // premultiplied in-scattered radiance (rgb), transmittance (w)
    float depth;  // distance (m) to the first cloud; NO_HIT (shell.glsl.h) where there is none
    float weight; // temporal history: marches accumulated in the pixel (0 = a fallback value)
    float flash;  // the masked lightning flash at unit intensity (lightning.glsl.h), premultiplied
    float debug;  // for the viewer's debug views only, never read by a pass: texelDebugCode of
                  // the texel's TEMPORAL_SOURCE_* and its march's density samples
};
CONST_INT CLOUD_TEXEL_ROWS = 2;

// CloudTexel.debug: a source (0-3) and a sample count (a whole number, exact in float up to
// 2^22) in one float, so the record stays 32 bytes.
inline float texelDebugCode(int source, float densitySamples) {
    return float(source) + 4.0f * floor(densitySamples);
}
inline int texelDebugSource(float code) {
    return int(code - 4.0f * floor(code * 0.25f));
}
inline float texelDebugSamples(float code) {
    return floor(code * 0.25f);
}

// One cell of the light shafts' grid (shaft_grid.glsl.h): the two parts of a shaft ray's change
// (lightShaftsParts) and the two distances the upsample compares a pixel's with.
struct ShaftTexel {
    vec4 front;  // the light lost in front of the first cloud (rgb); w: the shafts' length (m)
    vec4 behind; // the light lost behind it, before its transmittance (rgb); w: the split (m)
};
CONST_INT SHAFT_TEXEL_ROWS = 2;

// Totals of a frame, summed on the device (per workgroup, then atomically) so that statistics
// need no per-pixel readback. The sample counts are 64-bit, kept as (low, high) word pairs.
struct FrameCounters {
    uint densitySamplesLow; // density evaluations along view rays
    uint densitySamplesHigh;
    uint lightSamplesLow; // density evaluations along light rays
    uint lightSamplesHigh;
    uint marched; // resolved pixels by source (TEMPORAL_SOURCE_*)
    uint reprojected;
    uint fallback;
    uint entering;        // the block march's entering marches (sample_gather.glsl.h)
    uint cloudSamplesLow; // of the density samples, those in cloud (with extinction)
    uint cloudSamplesHigh;
    uint emptySkipsLow; // the march's skips over proven empty space (no texture read)
    uint emptySkipsHigh;
};

// ---- render_clouds.comp: the march (the model's renderPixel). Full-frame mode marches every
// pixel of a tile; block mode (the temporal renderer) marches one pixel of every 4x4 block.
CONST_INT MARCH_CLOUD_PARAMS = 0;  // read-only CloudParams
CONST_INT MARCH_FRAME_PARAMS = 1;  // read-only FrameParams
CONST_INT MARCH_BASE_NOISE = 2;    // sampler3D, 128^3 RGBA8 with mips
CONST_INT MARCH_DETAIL_NOISE = 3;  // sampler3D, 32^3
CONST_INT MARCH_CURL_NOISE = 4;    // sampler2D, 128^2
CONST_INT MARCH_WEATHER_MAP = 5;   // sampler2D
CONST_INT MARCH_BLUE_NOISE = 6;    // sampler2D 64^2, read with texelFetch
CONST_INT MARCH_SCENE_DEPTH = 7;   // float[] at the frame's size (one float when unused)
CONST_INT MARCH_OUT_CLOUD = 8;     // CloudTexel[] per pixel, or per block in block mode
CONST_INT MARCH_OUT_COMPOSITE = 9; // vec4[] per pixel: clouds over the background (full frames)
CONST_INT MARCH_COUNTERS = 10;     // FrameCounters
CONST_INT MARCH_ATMOSPHERE = 11;   // vec4[] the atmosphere's tables (atmosphere.glsl.h)
CONST_INT MARCH_HIGH_CLOUDS = 12;  // sampler2D 512^2, the high-altitude layer (the composite's)
CONST_INT MARCH_TERRAIN = 13;      // float[] the terrain's height field (one float when off)
CONST_INT MARCH_CLOUD_SHADOW = 14; // vec4[] the clouds' shadow map (one texel when off)
// Block mode of a gathering frame (built with FEATURE_GATHER): the previous frame's parameters
// and the entering ring its entering blocks' extra marches go to (sample_gather.glsl.h's
// enteringMarchCount; CloudTexel[], enteringRingRecords; one record when unused).
CONST_INT MARCH_PREVIOUS_FRAME = 15; // read-only FrameParams
CONST_INT MARCH_OUT_ENTERING = 16;
// uint[] the base noise's clearance field (noise_clearance.glsl.h; one zero when there is none)
CONST_INT MARCH_NOISE_CLEARANCE = 17;
CONST_INT MARCH_BINDING_COUNT = 18;

// A dispatch's first pixel (or block) is its base workgroup (vkCmdDispatchBase), and the frame of a
// sequence is FrameParams.sequenceFrame: neither is a push constant (see ResolvePush).
struct MarchPush {
    int blockMode; // 0: every pixel; 1: one pixel per block (the temporal path)
    int unused0;
    int unused1;
    int unused2;
};

// ---- temporal_resolve.comp: every full-resolution pixel from this frame's block marches and
// the previous frame's result (the model's resolveTemporalPixel and its composite).
CONST_INT RESOLVE_CLOUD_PARAMS = 0;   // read-only CloudParams
CONST_INT RESOLVE_FRAME_PARAMS = 1;   // read-only FrameParams of this frame
CONST_INT RESOLVE_PREVIOUS_FRAME = 2; // read-only FrameParams of the history's frame
CONST_INT RESOLVE_HISTORY = 3;        // CloudTexel[] per pixel: the previous result (read)
CONST_INT RESOLVE_FRESH = 4;          // CloudTexel[] per block: this frame's marches
CONST_INT RESOLVE_OUT_HISTORY = 5;    // CloudTexel[] per pixel: this frame's result
CONST_INT RESOLVE_OUT_COMPOSITE = 6;  // vec4[] per pixel: the displayed image
CONST_INT RESOLVE_SCENE_DEPTH = 7;    // float[] at the frame's size (one float when unused)
CONST_INT RESOLVE_COUNTERS = 8;       // FrameCounters (pixels by source)
CONST_INT RESOLVE_ATMOSPHERE = 9;     // vec4[] the atmosphere's tables (the composite's sky)
// The base noise and weather map, for the ground's cloud shadow in the composite (ground.glsl.h,
// base-shape samples only).
CONST_INT RESOLVE_BASE_NOISE = 10;
CONST_INT RESOLVE_WEATHER_MAP = 11;
CONST_INT RESOLVE_HIGH_CLOUDS = 12; // sampler2D, the high-altitude layer behind the clouds
CONST_INT RESOLVE_TERRAIN = 13; // float[] the terrain's height field (the composite's background)
CONST_INT RESOLVE_CLOUD_SHADOW = 14; // vec4[] the clouds' shadow map (one texel when off)
// ShaftTexel[] per cell of the shafts' grid (shaft_grid.glsl.h; one texel when unused): written by
// the grid dispatch (the pipeline specialised with PASS_SHAFT_GRID), read by the resolve that
// follows it.
CONST_INT RESOLVE_SHAFTS = 15;
// BackgroundLight[] per pixel (pixel.glsl.h): written by the background dispatch (the pipeline
// specialised with PASS_FILL_BACKGROUND) when the background changed, read by every resolve.
CONST_INT RESOLVE_BACKGROUND = 16;
// BackgroundTexel[] per pixel: the background under this frame's clouds, made from the light by
// the PASS_SHADE_BACKGROUND dispatch when the light or the clouds changed; what the resolve reads.
CONST_INT RESOLVE_BACKGROUND_SEEN = 17;
// The ground fallback's list (below): written by the background dispatch built without
// FEATURE_GROUND_FALLBACK, read by the indirect dispatch over it (PASS_GROUND_FALLBACK).
CONST_INT RESOLVE_GROUND_FALLBACK = 18;
// The moving camera's gather of earlier marches (sample_gather.glsl.h): FrameParams[] of the
// frames in the ring, by ring position (GATHER_MAX_FRAMES of them), and CloudTexel[] of their
// marches, gatherSlotBlocks a position (one record when render.moving_gather_frames is 0).
CONST_INT RESOLVE_GATHER_FRAMES = 19;
CONST_INT RESOLVE_GATHER_RING = 20;
CONST_INT RESOLVE_GATHER_ENTERING = 21; // CloudTexel[]: the entering ring (sample_gather.glsl.h)
CONST_INT RESOLVE_BINDING_COUNT = 22;

// The pixels whose background needs the ground's two-sample cloud shadow (pixel.glsl.h's
// backgroundTexelFrom says which), as a background pass built without FEATURE_GROUND_FALLBACK
// lists them: GROUND_FALLBACK_HEADER_WORDS words, the first three a VkDispatchIndirectCommand
// (x: groups of GROUND_FALLBACK_GROUP listed pixels, y and z 1) and the fourth the number
// listed, then the listed pixels' indices in the image (y * width + x). The host resets the
// header to (0, 1, 1, 0) before the pass.
CONST_INT GROUND_FALLBACK_HEADER_WORDS = 4;
CONST_INT GROUND_FALLBACK_GROUP = 64; // the background shaders' 8x8 workgroup

// Only values with a few possible settings belong in a push-constant block: lavapipe compiles and
// keeps a shader variant per distinct value (FrameParams.sequenceFrame and secondsSincePrevious
// carry the per-frame ones).
struct ResolvePush {
    int haveHistory;
    int unused0;
    int unused1;
    int unused2;
};

// ---- upsample_clouds.comp: a reduced-resolution cloud pass (render.cloud_resolution < 1)
// brought to every output pixel on the device (the model's upsampleCloudPass).
CONST_INT UPSAMPLE_CLOUD_PARAMS = 0;  // read-only CloudParams
CONST_INT UPSAMPLE_FRAME_PARAMS = 1;  // read-only FrameParams of the output
CONST_INT UPSAMPLE_IN_CLOUD = 2;      // CloudTexel[] per pass pixel (a march or a history)
CONST_INT UPSAMPLE_SCENE_DEPTH = 3;   // float[] at the output size (one float when unused)
CONST_INT UPSAMPLE_OUT_CLOUD = 4;     // CloudTexel[] per output pixel
CONST_INT UPSAMPLE_OUT_COMPOSITE = 5; // vec4[] per output pixel: the displayed image
CONST_INT UPSAMPLE_ATMOSPHERE = 6;    // vec4[] the atmosphere's tables (the composite's sky)
// The base noise and weather map, for the ground's cloud shadow in the composite (ground.glsl.h,
// base-shape samples only).
CONST_INT UPSAMPLE_BASE_NOISE = 7;
CONST_INT UPSAMPLE_WEATHER_MAP = 8;
CONST_INT UPSAMPLE_HIGH_CLOUDS = 9; // sampler2D, the high-altitude layer behind the clouds
CONST_INT UPSAMPLE_TERRAIN = 10; // float[] the terrain's height field (the composite's background)
CONST_INT UPSAMPLE_CLOUD_SHADOW = 11; // vec4[] the clouds' shadow map (one texel when off)
// BackgroundLight[] per output pixel, as RESOLVE_BACKGROUND is per pass pixel.
CONST_INT UPSAMPLE_BACKGROUND = 12;
CONST_INT UPSAMPLE_BACKGROUND_SEEN = 13; // BackgroundTexel[] per output pixel, as the resolve's
// ShaftTexel[] the light shafts' grid over the pass's image, made by the resolve's grid
// dispatch (one cell when there is none: UpsamplePush.shaftGrid 0).
CONST_INT UPSAMPLE_SHAFTS = 14;
CONST_INT UPSAMPLE_GROUND_FALLBACK = 15; // the ground fallback's list, as the resolve's
// BackgroundTexel[] per pass pixel (RESOLVE_BACKGROUND_SEEN's buffer): read by the pipeline built
// with PASS_UPSAMPLED_BACKGROUND (upsample.glsl.h's upsampledBackground).
CONST_INT UPSAMPLE_PASS_BACKGROUND_SEEN = 16;
CONST_INT UPSAMPLE_BINDING_COUNT = 17;

struct UpsamplePush {
    int passWidth;
    int passHeight;
    int shaftGrid; // 1: the pass made the light shafts' grid (UPSAMPLE_SHAFTS) over its image
    int unused1;
};

// ---- cloud_shadow.comp: the clouds' shadow map of a frame, one invocation per texel (the
// model's cloudShadowMapTexel, cloud_shadow.glsl.h), before the passes that read it.
CONST_INT SHADOW_CLOUD_PARAMS = 0; // CloudParams (a read-only storage buffer, as every pass's)
CONST_INT SHADOW_BASE_NOISE = 1;   // sampler3D
CONST_INT SHADOW_DETAIL_NOISE = 2; // sampler3D
CONST_INT SHADOW_CURL_NOISE = 3;   // sampler2D
CONST_INT SHADOW_WEATHER_MAP = 4;  // sampler2D
CONST_INT SHADOW_OUT_MAP = 5;      // vec4[] resolution^2 texels
CONST_INT SHADOW_BINDING_COUNT = 6;

struct ShadowPush {
    int originX; // first map texel of this dispatch
    int originY;
    int endX; // one past the last map texel of the region being made
    int endY;
};

// ---- atmosphere_tables.comp: one of the atmosphere's tables (atmosphere.glsl.h's
// atmosphereTableTexel), one invocation per texel, written into the buffer the march, resolve
// and upsample read (their *_ATMOSPHERE bindings); one dispatch per table, in the model's order
// with a barrier between them, whenever the sun or the atmosphere's inputs change.
CONST_INT TABLES_SKY_PARAMS = 0; // read-only SkyParams: the atmosphere, the sun and the moon
CONST_INT TABLES_ATMOSPHERE = 1; // vec4[] ATMOSPHERE_LUT_TEXELS: read (earlier tables), written
CONST_INT TABLES_BINDING_COUNT = 2;

// The table is a push constant of ATMOSPHERE_TABLE_COUNT values: few, as ResolvePush asks.
struct TablesPush {
    int table; // ATMOSPHERE_TABLE_*
    int unused0;
    int unused1;
    int unused2;
};

#ifdef __cplusplus
static_assert(sizeof(CloudTexel) == 32, "CloudTexel must match the GLSL std430 layout");
static_assert(sizeof(CloudTexel) == CLOUD_TEXEL_ROWS * 16, "CloudTexel is its texel rows");
static_assert(sizeof(ShaftTexel) == 32, "ShaftTexel must match the GLSL std430 layout");
static_assert(sizeof(ShaftTexel) == SHAFT_TEXEL_ROWS * 16, "ShaftTexel is its texel rows");
static_assert(sizeof(FrameCounters) == 48, "FrameCounters must match the GLSL std430 layout");
static_assert(sizeof(MarchPush) == 16, "MarchPush must match the GLSL push-constant block");
static_assert(sizeof(ResolvePush) == 16, "ResolvePush must match the GLSL push-constant block");
static_assert(sizeof(UpsamplePush) == 16, "UpsamplePush must match the GLSL push-constant block");
static_assert(sizeof(ShadowPush) == 16, "ShadowPush must match the GLSL push-constant block");
static_assert(sizeof(TablesPush) == 16, "TablesPush must match the GLSL push-constant block");

// ---- The binding tables the host builds its descriptor sets from (C++ only).
//
// The parameter blocks are read-only storage buffers, not uniform buffers: Mesa's lavapipe
// (22.3, Debian 12) inlines the values of uniform buffers and push constants that steer loops into
// a freshly compiled copy of the shader at every bind, and never frees it: a full march compile
// and about 6 MB per frame. Storage buffers are never inlined. The layouts are the same (every
// struct is rows of 16 bytes, so std140 and std430 agree).
//
// The per-pixel records and the world's tables (history, marches, background, composite,
// atmosphere, terrain, shadow map) are bound as texel buffers over the same bytes: uniform texel
// buffers where a pass only reads them, storage texel buffers where it writes them. On lavapipe a
// storage-buffer access is a loop over the SIMD lanes with a branch per lane and component, a
// texel fetch or image load/store a vector gather or scatter: the resolve and the background
// pass took about a third less time (docs/PERFORMANCE.md, 2026-12-06). Storage buffers stay for
// the parameter blocks, the counters, the ground fallback's list and the scene depth.

enum class DescriptorKind {
    UniformBuffer,
    StorageBuffer,
    CombinedImageSampler,
    UniformTexelBuffer, // read with texelFetch (samplerBuffer)
    StorageTexelBuffer, // read and written with imageLoad/imageStore (imageBuffer, rgba32f)
};

struct BindingSpec {
    int binding;
    DescriptorKind kind;
    const char* name; // for messages
};

// A pass: its shader, its bindings (index i holds binding i) and its push-constant size.
struct PassInterface {
    const char* shader;
    const BindingSpec* bindings;
    int bindingCount;
    unsigned pushConstantBytes;
};

inline constexpr BindingSpec MARCH_BINDINGS[] = {
    {MARCH_CLOUD_PARAMS, DescriptorKind::StorageBuffer, "cloud parameters"},
    {MARCH_FRAME_PARAMS, DescriptorKind::StorageBuffer, "frame parameters"},
    {MARCH_BASE_NOISE, DescriptorKind::CombinedImageSampler, "base noise"},
    {MARCH_DETAIL_NOISE, DescriptorKind::CombinedImageSampler, "detail noise"},
    {MARCH_CURL_NOISE, DescriptorKind::CombinedImageSampler, "curl noise"},
    {MARCH_WEATHER_MAP, DescriptorKind::CombinedImageSampler, "weather map"},
    {MARCH_BLUE_NOISE, DescriptorKind::CombinedImageSampler, "blue noise"},
    {MARCH_SCENE_DEPTH, DescriptorKind::StorageBuffer, "scene depth"},
    {MARCH_OUT_CLOUD, DescriptorKind::StorageTexelBuffer, "cloud output"},
    {MARCH_OUT_COMPOSITE, DescriptorKind::StorageTexelBuffer, "composite output"},
    {MARCH_COUNTERS, DescriptorKind::StorageBuffer, "frame counters"},
    {MARCH_ATMOSPHERE, DescriptorKind::UniformTexelBuffer, "atmosphere tables"},
    {MARCH_HIGH_CLOUDS, DescriptorKind::CombinedImageSampler, "high-altitude clouds"},
    {MARCH_TERRAIN, DescriptorKind::UniformTexelBuffer, "terrain height field"},
    {MARCH_CLOUD_SHADOW, DescriptorKind::UniformTexelBuffer, "cloud shadow map"},
    {MARCH_PREVIOUS_FRAME, DescriptorKind::StorageBuffer, "previous frame parameters"},
    {MARCH_OUT_ENTERING, DescriptorKind::StorageTexelBuffer, "entering marches"},
    {MARCH_NOISE_CLEARANCE, DescriptorKind::UniformTexelBuffer, "base noise clearance"},
};

inline constexpr BindingSpec RESOLVE_BINDINGS[] = {
    {RESOLVE_CLOUD_PARAMS, DescriptorKind::StorageBuffer, "cloud parameters"},
    {RESOLVE_FRAME_PARAMS, DescriptorKind::StorageBuffer, "frame parameters"},
    {RESOLVE_PREVIOUS_FRAME, DescriptorKind::StorageBuffer, "previous frame parameters"},
    {RESOLVE_HISTORY, DescriptorKind::UniformTexelBuffer, "history"},
    {RESOLVE_FRESH, DescriptorKind::UniformTexelBuffer, "fresh marches"},
    {RESOLVE_OUT_HISTORY, DescriptorKind::StorageTexelBuffer, "history output"},
    {RESOLVE_OUT_COMPOSITE, DescriptorKind::StorageTexelBuffer, "composite output"},
    {RESOLVE_SCENE_DEPTH, DescriptorKind::StorageBuffer, "scene depth"},
    {RESOLVE_COUNTERS, DescriptorKind::StorageBuffer, "frame counters"},
    {RESOLVE_ATMOSPHERE, DescriptorKind::UniformTexelBuffer, "atmosphere tables"},
    {RESOLVE_BASE_NOISE, DescriptorKind::CombinedImageSampler, "base noise"},
    {RESOLVE_WEATHER_MAP, DescriptorKind::CombinedImageSampler, "weather map"},
    {RESOLVE_HIGH_CLOUDS, DescriptorKind::CombinedImageSampler, "high-altitude clouds"},
    {RESOLVE_TERRAIN, DescriptorKind::UniformTexelBuffer, "terrain height field"},
    {RESOLVE_CLOUD_SHADOW, DescriptorKind::UniformTexelBuffer, "cloud shadow map"},
    {RESOLVE_SHAFTS, DescriptorKind::StorageTexelBuffer, "light shafts grid"},
    {RESOLVE_BACKGROUND, DescriptorKind::StorageTexelBuffer, "background light"},
    {RESOLVE_BACKGROUND_SEEN, DescriptorKind::StorageTexelBuffer, "background"},
    {RESOLVE_GROUND_FALLBACK, DescriptorKind::StorageBuffer, "ground fallback list"},
    {RESOLVE_GATHER_FRAMES, DescriptorKind::StorageBuffer, "gathered frames' parameters"},
    {RESOLVE_GATHER_RING, DescriptorKind::UniformTexelBuffer, "gathered marches"},
    {RESOLVE_GATHER_ENTERING, DescriptorKind::UniformTexelBuffer, "entering marches"},
};

inline constexpr BindingSpec UPSAMPLE_BINDINGS[] = {
    {UPSAMPLE_CLOUD_PARAMS, DescriptorKind::StorageBuffer, "cloud parameters"},
    {UPSAMPLE_FRAME_PARAMS, DescriptorKind::StorageBuffer, "frame parameters"},
    {UPSAMPLE_IN_CLOUD, DescriptorKind::UniformTexelBuffer, "reduced-resolution pass"},
    {UPSAMPLE_SCENE_DEPTH, DescriptorKind::StorageBuffer, "scene depth"},
    {UPSAMPLE_OUT_CLOUD, DescriptorKind::StorageTexelBuffer, "cloud output"},
    {UPSAMPLE_OUT_COMPOSITE, DescriptorKind::StorageTexelBuffer, "composite output"},
    {UPSAMPLE_ATMOSPHERE, DescriptorKind::UniformTexelBuffer, "atmosphere tables"},
    {UPSAMPLE_BASE_NOISE, DescriptorKind::CombinedImageSampler, "base noise"},
    {UPSAMPLE_WEATHER_MAP, DescriptorKind::CombinedImageSampler, "weather map"},
    {UPSAMPLE_HIGH_CLOUDS, DescriptorKind::CombinedImageSampler, "high-altitude clouds"},
    {UPSAMPLE_TERRAIN, DescriptorKind::UniformTexelBuffer, "terrain height field"},
    {UPSAMPLE_CLOUD_SHADOW, DescriptorKind::UniformTexelBuffer, "cloud shadow map"},
    {UPSAMPLE_BACKGROUND, DescriptorKind::StorageTexelBuffer, "background light"},
    {UPSAMPLE_BACKGROUND_SEEN, DescriptorKind::StorageTexelBuffer, "background"},
    {UPSAMPLE_SHAFTS, DescriptorKind::UniformTexelBuffer, "light shafts' grid"},
    {UPSAMPLE_GROUND_FALLBACK, DescriptorKind::StorageBuffer, "ground fallback list"},
    {UPSAMPLE_PASS_BACKGROUND_SEEN, DescriptorKind::UniformTexelBuffer, "pass background"},
};

inline constexpr BindingSpec SHADOW_BINDINGS[] = {
    {SHADOW_CLOUD_PARAMS, DescriptorKind::StorageBuffer, "cloud parameters"},
    {SHADOW_BASE_NOISE, DescriptorKind::CombinedImageSampler, "base noise"},
    {SHADOW_DETAIL_NOISE, DescriptorKind::CombinedImageSampler, "detail noise"},
    {SHADOW_CURL_NOISE, DescriptorKind::CombinedImageSampler, "curl noise"},
    {SHADOW_WEATHER_MAP, DescriptorKind::CombinedImageSampler, "weather map"},
    {SHADOW_OUT_MAP, DescriptorKind::StorageTexelBuffer, "cloud shadow map output"},
};

inline constexpr BindingSpec TABLES_BINDINGS[] = {
    {TABLES_SKY_PARAMS, DescriptorKind::StorageBuffer, "sky parameters"},
    {TABLES_ATMOSPHERE, DescriptorKind::StorageBuffer, "atmosphere tables"},
};

// Every table lists bindings 0..count-1 in order, so a binding can be looked up by its number.
template <int N> constexpr bool bindingsAreDense(const BindingSpec (&table)[N], int count) {
    if (N != count)
        return false;
    for (int i = 0; i < N; ++i)
        if (table[i].binding != i)
            return false;
    return true;
}
static_assert(bindingsAreDense(MARCH_BINDINGS, MARCH_BINDING_COUNT), "MARCH_BINDINGS order");
static_assert(bindingsAreDense(RESOLVE_BINDINGS, RESOLVE_BINDING_COUNT), "RESOLVE_BINDINGS order");
static_assert(bindingsAreDense(UPSAMPLE_BINDINGS, UPSAMPLE_BINDING_COUNT),
              "UPSAMPLE_BINDINGS order");
static_assert(bindingsAreDense(SHADOW_BINDINGS, SHADOW_BINDING_COUNT), "SHADOW_BINDINGS order");
static_assert(bindingsAreDense(TABLES_BINDINGS, TABLES_BINDING_COUNT), "TABLES_BINDINGS order");

inline constexpr PassInterface MARCH_PASS = {"render_clouds.comp", MARCH_BINDINGS,
                                             MARCH_BINDING_COUNT, sizeof(MarchPush)};
inline constexpr PassInterface UPSAMPLE_PASS = {"upsample_clouds.comp", UPSAMPLE_BINDINGS,
                                                UPSAMPLE_BINDING_COUNT, sizeof(UpsamplePush)};
inline constexpr PassInterface SHADOW_PASS = {"cloud_shadow.comp", SHADOW_BINDINGS,
                                              SHADOW_BINDING_COUNT, sizeof(ShadowPush)};
inline constexpr PassInterface RESOLVE_PASS = {"temporal_resolve.comp", RESOLVE_BINDINGS,
                                               RESOLVE_BINDING_COUNT, sizeof(ResolvePush)};
inline constexpr PassInterface TABLES_PASS = {"atmosphere_tables.comp", TABLES_BINDINGS,
                                              TABLES_BINDING_COUNT, sizeof(TablesPush)};
#endif

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
