// The GPU interface checked, not restated: every embedded SPIR-V module is reflected with
// SPIRV-Cross and compared with what the C++ declared for the pipelines that use it (each binding's
// number, descriptor type and array size, the push-constant bytes), and every shared struct the
// shaders see (shared/types.h) with the C++ struct of that name, member by member (offsetof; read
// from an unoptimised copy of each module, whose names the optimiser has not stripped).
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <spirv_cross_c.h>

#include "gpu_fixture.h"
#include "vk/shader_registry.h"

namespace penumbra::test {
namespace {

// ---- The C++ side of the shared structs: member names and offsets, from the compiler ----
struct MemberLayout {
    std::string name;
    size_t offset;
};
struct StructLayout {
    size_t size;
    std::vector<MemberLayout> members;
};

#define MEMBER(S, m) MemberLayout{#m, offsetof(gpu::S, m)}
#define STRUCT(S, ...) {#S, StructLayout{sizeof(gpu::S), {__VA_ARGS__}}}

const std::map<std::string, StructLayout>& sharedStructs() {
    static const std::map<std::string, StructLayout> table{
        STRUCT(FrameUniforms, MEMBER(FrameUniforms, viewProj), MEMBER(FrameUniforms, invViewProj),
               MEMBER(FrameUniforms, previousViewProj), MEMBER(FrameUniforms, reprojection),
               MEMBER(FrameUniforms, eye), MEMBER(FrameUniforms, farPlane), MEMBER(FrameUniforms, width),
               MEMBER(FrameUniforms, height), MEMBER(FrameUniforms, lightCount), MEMBER(FrameUniforms, aov),
               MEMBER(FrameUniforms, giValid), MEMBER(FrameUniforms, visibilityIds), MEMBER(FrameUniforms, probeX),
               MEMBER(FrameUniforms, probeY), MEMBER(FrameUniforms, pixelSpread), MEMBER(FrameUniforms, pad0),
               MEMBER(FrameUniforms, pad1), MEMBER(FrameUniforms, pad2)),
        STRUCT(PixelProbe, MEMBER(PixelProbe, finalRadiance), MEMBER(PixelProbe, surface), MEMBER(PixelProbe, direct),
               MEMBER(PixelProbe, eyeDistance), MEMBER(PixelProbe, indirect), MEMBER(PixelProbe, shadowVisibility),
               MEMBER(PixelProbe, irradiance), MEMBER(PixelProbe, shadowLayer), MEMBER(PixelProbe, albedo),
               MEMBER(PixelProbe, transmittance), MEMBER(PixelProbe, normal), MEMBER(PixelProbe, shadingModel),
               MEMBER(PixelProbe, position), MEMBER(PixelProbe, pad0), MEMBER(PixelProbe, velocity),
               MEMBER(PixelProbe, pad1), MEMBER(PixelProbe, pad2)),
        STRUCT(GpuLight, MEMBER(GpuLight, position), MEMBER(GpuLight, type), MEMBER(GpuLight, direction),
               MEMBER(GpuLight, range), MEMBER(GpuLight, radiance), MEMBER(GpuLight, shadowIndex),
               MEMBER(GpuLight, cosInner), MEMBER(GpuLight, cosOuter), MEMBER(GpuLight, normalOffset),
               MEMBER(GpuLight, perspective), MEMBER(GpuLight, shadowTexelSize), MEMBER(GpuLight, pad0),
               MEMBER(GpuLight, pad1), MEMBER(GpuLight, pad2), MEMBER(GpuLight, shadowViewProj)),
        STRUCT(GpuMaterial, MEMBER(GpuMaterial, baseColor), MEMBER(GpuMaterial, texture),
               MEMBER(GpuMaterial, alphaMode), MEMBER(GpuMaterial, doubleSided), MEMBER(GpuMaterial, pad0),
               MEMBER(GpuMaterial, alphaCutoff), MEMBER(GpuMaterial, pad1), MEMBER(GpuMaterial, pad2),
               MEMBER(GpuMaterial, pad3)),
        STRUCT(GpuInstance, MEMBER(GpuInstance, model), MEMBER(GpuInstance, normal), MEMBER(GpuInstance, toPrevious),
               MEMBER(GpuInstance, mirrored), MEMBER(GpuInstance, firstDrawnTriangle), MEMBER(GpuInstance, pad0),
               MEMBER(GpuInstance, pad1)),
        STRUCT(DrawPush, MEMBER(DrawPush, viewIndex), MEMBER(DrawPush, material), MEMBER(DrawPush, pad0),
               MEMBER(DrawPush, triangleBase)),
        STRUCT(DebugViewPush, MEMBER(DebugViewPush, aov), MEMBER(DebugViewPush, layer), MEMBER(DebugViewPush, pad0),
               MEMBER(DebugViewPush, pad1)),
        STRUCT(TonemapPush, MEMBER(TonemapPush, scale), MEMBER(TonemapPush, bias), MEMBER(TonemapPush, mode),
               MEMBER(TonemapPush, autoExposure)),
        STRUCT(AutoExposureState, MEMBER(AutoExposureState, adaptedLog), MEMBER(AutoExposureState, exposure),
               MEMBER(AutoExposureState, logAverage), MEMBER(AutoExposureState, valid)),
        STRUCT(AutoExposurePush, MEMBER(AutoExposurePush, rate), MEMBER(AutoExposurePush, lowFraction),
               MEMBER(AutoExposurePush, highFraction), MEMBER(AutoExposurePush, pad)),
        STRUCT(GpuRsmLayer, MEMBER(GpuRsmLayer, viewProj), MEMBER(GpuRsmLayer, invViewProj),
               MEMBER(GpuRsmLayer, texelSize), MEMBER(GpuRsmLayer, perspective), MEMBER(GpuRsmLayer, light),
               MEMBER(GpuRsmLayer, cascade), MEMBER(GpuRsmLayer, lastCascade), MEMBER(GpuRsmLayer, radiusScale),
               MEMBER(GpuRsmLayer, pad0), MEMBER(GpuRsmLayer, pad1)),
        STRUCT(RsmPush, MEMBER(RsmPush, mode), MEMBER(RsmPush, sampleCount), MEMBER(RsmPush, layerCount),
               MEMBER(RsmPush, lowResFactor), MEMBER(RsmPush, width), MEMBER(RsmPush, height),
               MEMBER(RsmPush, rsmResolution), MEMBER(RsmPush, bilinearVpls), MEMBER(RsmPush, normalThreshold),
               MEMBER(RsmPush, distanceThreshold), MEMBER(RsmPush, radius), MEMBER(RsmPush, frameSeed),
               MEMBER(RsmPush, visibility), MEMBER(RsmPush, visibilityRays), MEMBER(RsmPush, paperWeights),
               MEMBER(RsmPush, lanesPerReceiver), MEMBER(RsmPush, farByFlux), MEMBER(RsmPush, shiftedRadii),
               MEMBER(RsmPush, visibilityPoints), MEMBER(RsmPush, gradientPhase)),
        STRUCT(GpuGradientSample, MEMBER(GpuGradientSample, position), MEMBER(GpuGradientSample, luminance),
               MEMBER(GpuGradientSample, normal), MEMBER(GpuGradientSample, hair)),
        STRUCT(RsmFluxPush, MEMBER(RsmFluxPush, rsmResolution), MEMBER(RsmFluxPush, layerCount),
               MEMBER(RsmFluxPush, curve), MEMBER(RsmFluxPush, step), MEMBER(RsmFluxPush, seed),
               MEMBER(RsmFluxPush, pad0), MEMBER(RsmFluxPush, pad1), MEMBER(RsmFluxPush, pad2)),
        STRUCT(GpuOccupancyGrid, MEMBER(GpuOccupancyGrid, origin), MEMBER(GpuOccupancyGrid, voxelSize),
               MEMBER(GpuOccupancyGrid, dims), MEMBER(GpuOccupancyGrid, firstBrickWord),
               MEMBER(GpuOccupancyGrid, skyFirstWord), MEMBER(GpuOccupancyGrid, pad0), MEMBER(GpuOccupancyGrid, pad1),
               MEMBER(GpuOccupancyGrid, pad2)),
        STRUCT(OccupancyPush, MEMBER(OccupancyPush, triangleCount), MEMBER(OccupancyPush, walkChunks),
               MEMBER(OccupancyPush, chunkCapacity), MEMBER(OccupancyPush, pad0)),
        STRUCT(GiAccumulatePush, MEMBER(GiAccumulatePush, minWeight), MEMBER(GiAccumulatePush, changeWeight),
               MEMBER(GiAccumulatePush, historyValid), MEMBER(GiAccumulatePush, changePixels),
               MEMBER(GiAccumulatePush, lagTolerance), MEMBER(GiAccumulatePush, pad0), MEMBER(GiAccumulatePush, pad1),
               MEMBER(GiAccumulatePush, pad2)),
        STRUCT(GiFilterPush, MEMBER(GiFilterPush, step), MEMBER(GiFilterPush, firstIteration),
               MEMBER(GiFilterPush, luminanceSigma), MEMBER(GiFilterPush, pad0)),
        STRUCT(RsmResolvePush, MEMBER(RsmResolvePush, rsmResolution), MEMBER(RsmResolvePush, idResolution),
               MEMBER(RsmResolvePush, pad0), MEMBER(RsmResolvePush, pad1)),
        STRUCT(VisibilityResolvePush, MEMBER(VisibilityResolvePush, width), MEMBER(VisibilityResolvePush, height),
               MEMBER(VisibilityResolvePush, pad0), MEMBER(VisibilityResolvePush, pad1)),
        STRUCT(GpuLpvCascade, MEMBER(GpuLpvCascade, origin), MEMBER(GpuLpvCascade, cellSize)),
        STRUCT(GpuVpl, MEMBER(GpuVpl, position), MEMBER(GpuVpl, exists), MEMBER(GpuVpl, normal), MEMBER(GpuVpl, area),
               MEMBER(GpuVpl, flux), MEMBER(GpuVpl, pad0)),
        STRUCT(LpvPush, MEMBER(LpvPush, resolution), MEMBER(LpvPush, cascadeCount), MEMBER(LpvPush, iteration),
               MEMBER(LpvPush, farFromIteration), MEMBER(LpvPush, vplCount), MEMBER(LpvPush, rsmResolution),
               MEMBER(LpvPush, vplResolution), MEMBER(LpvPush, layerCount), MEMBER(LpvPush, occlusion),
               MEMBER(LpvPush, blendCells), MEMBER(LpvPush, cameraGeometryStep), MEMBER(LpvPush, voxelFaces),
               MEMBER(LpvPush, sliceAxis), MEMBER(LpvPush, sliceIndex), MEMBER(LpvPush, pad0),
               MEMBER(LpvPush, pad1), MEMBER(LpvPush, cascades)),
        STRUCT(GpuShadowLight, MEMBER(GpuShadowLight, firstLayer), MEMBER(GpuShadowLight, layerCount),
               MEMBER(GpuShadowLight, kind), MEMBER(GpuShadowLight, filterMode), MEMBER(GpuShadowLight, normalOffset),
               MEMBER(GpuShadowLight, penumbraScale), MEMBER(GpuShadowLight, pad0), MEMBER(GpuShadowLight, pad1)),
        STRUCT(GpuShadowLayer, MEMBER(GpuShadowLayer, viewProj), MEMBER(GpuShadowLayer, texelSize),
               MEMBER(GpuShadowLayer, zNear), MEMBER(GpuShadowLayer, zFar), MEMBER(GpuShadowLayer, discScale),
               MEMBER(GpuShadowLayer, splitNear), MEMBER(GpuShadowLayer, splitFar), MEMBER(GpuShadowLayer, pad0),
               MEMBER(GpuShadowLayer, pad1), MEMBER(GpuShadowLayer, projection), MEMBER(GpuShadowLayer, momentLayer),
               MEMBER(GpuShadowLayer, momentFilter), MEMBER(GpuShadowLayer, pad2)),
        STRUCT(GpuShadowParams, MEMBER(GpuShadowParams, pcfRadius), MEMBER(GpuShadowParams, pcssMaxRadius),
               MEMBER(GpuShadowParams, cascadeBlend), MEMBER(GpuShadowParams, pad0), MEMBER(GpuShadowParams, moments),
               MEMBER(GpuShadowParams, resolution), MEMBER(GpuShadowParams, blurRadius),
               MEMBER(GpuShadowParams, shadowedLights), MEMBER(GpuShadowParams, pad1),
               MEMBER(GpuShadowParams, poisson)),
        STRUCT(ShadowDrawPush, MEMBER(ShadowDrawPush, viewIndex), MEMBER(ShadowDrawPush, material),
               MEMBER(ShadowDrawPush, firstLayer), MEMBER(ShadowDrawPush, layerCount),
               MEMBER(ShadowDrawPush, triangleBase), MEMBER(ShadowDrawPush, pad0), MEMBER(ShadowDrawPush, pad1),
               MEMBER(ShadowDrawPush, pad2), MEMBER(ShadowDrawPush, paraboloidNear),
               MEMBER(ShadowDrawPush, paraboloidFar), MEMBER(ShadowDrawPush, paraboloidDiscScale),
               MEMBER(ShadowDrawPush, maxEdgeAngle)),
        STRUCT(GpuStrand, MEMBER(GpuStrand, color), MEMBER(GpuStrand, opacity)),
        STRUCT(GpuHairPoint, MEMBER(GpuHairPoint, position), MEMBER(GpuHairPoint, width), MEMBER(GpuHairPoint, tangent),
               MEMBER(GpuHairPoint, strand)),
        STRUCT(RibbonDrawPush, MEMBER(RibbonDrawPush, viewRow), MEMBER(RibbonDrawPush, pad0),
               MEMBER(RibbonDrawPush, pad1), MEMBER(RibbonDrawPush, pad2), MEMBER(RibbonDrawPush, view)),
        STRUCT(GpuDsmLight, MEMBER(GpuDsmLight, viewProj), MEMBER(GpuDsmLight, viewer),
               MEMBER(GpuDsmLight, viewerIsPoint), MEMBER(GpuDsmLight, texelSize), MEMBER(GpuDsmLight, projection),
               MEMBER(GpuDsmLight, layer), MEMBER(GpuDsmLight, resolution), MEMBER(GpuDsmLight, filterWidth),
               MEMBER(GpuDsmLight, depthBias), MEMBER(GpuDsmLight, normalOffset), MEMBER(GpuDsmLight, firstFace),
               MEMBER(GpuDsmLight, opacityMaps), MEMBER(GpuDsmLight, layerThickness), MEMBER(GpuDsmLight, pad0),
               MEMBER(GpuDsmLight, binarySearch)),
        STRUCT(DsmStats, MEMBER(DsmStats, fragments), MEMBER(DsmStats, hidden), MEMBER(DsmStats, overflow),
               MEMBER(DsmStats, runEntries), MEMBER(DsmStats, kept), MEMBER(DsmStats, beyondMaxList),
               MEMBER(DsmStats, longest), MEMBER(DsmStats, lists)),
        STRUCT(DsmPush, MEMBER(DsmPush, resolution), MEMBER(DsmPush, layerCount), MEMBER(DsmPush, nodeCapacity),
               MEMBER(DsmPush, maxList), MEMBER(DsmPush, bucketsPerTexel), MEMBER(DsmPush, pad0),
               MEMBER(DsmPush, pad1), MEMBER(DsmPush, pad2)),
        STRUCT(OitStats, MEMBER(OitStats, runEntries), MEMBER(OitStats, kept), MEMBER(OitStats, beyondMaxList),
               MEMBER(OitStats, longest), MEMBER(OitStats, fragments), MEMBER(OitStats, leftOut),
               MEMBER(OitStats, overflow), MEMBER(OitStats, pad0)),
        STRUCT(OitPush, MEMBER(OitPush, width), MEMBER(OitPush, height), MEMBER(OitPush, nodeCapacity),
               MEMBER(OitPush, bucketsPerPixel)),
        STRUCT(GpuMomentParams, MEMBER(GpuMomentParams, bleedReduction), MEMBER(GpuMomentParams, evsmPositive),
               MEMBER(GpuMomentParams, evsmNegative), MEMBER(GpuMomentParams, msmBias)),
        STRUCT(GpuRibbonView, MEMBER(GpuRibbonView, viewer), MEMBER(GpuRibbonView, viewerIsPoint),
               MEMBER(GpuRibbonView, pixelSize), MEMBER(GpuRibbonView, perspective), MEMBER(GpuRibbonView, minWidth),
               MEMBER(GpuRibbonView, pad0)),
        STRUCT(GpuDepthBuckets, MEMBER(GpuDepthBuckets, nearest), MEMBER(GpuDepthBuckets, perDepth),
               MEMBER(GpuDepthBuckets, perCell), MEMBER(GpuDepthBuckets, store)),
        STRUCT(DsmBuildPush, MEMBER(DsmBuildPush, viewRow), MEMBER(DsmBuildPush, material),
               MEMBER(DsmBuildPush, depthTestLight), MEMBER(DsmBuildPush, resolution), MEMBER(DsmBuildPush, view),
               MEMBER(DsmBuildPush, buckets)),
        STRUCT(DomBuildPush, MEMBER(DomBuildPush, viewRow), MEMBER(DomBuildPush, layers),
               MEMBER(DomBuildPush, layerThickness), MEMBER(DomBuildPush, resolution), MEMBER(DomBuildPush, view)),
        STRUCT(OitBuildPush, MEMBER(OitBuildPush, viewRow), MEMBER(OitBuildPush, material),
               MEMBER(OitBuildPush, width), MEMBER(OitBuildPush, pad0), MEMBER(OitBuildPush, view),
               MEMBER(OitBuildPush, buckets)),
        STRUCT(RasterTriangle, MEMBER(RasterTriangle, vertex0), MEMBER(RasterTriangle, vertex1),
               MEMBER(RasterTriangle, vertex2), MEMBER(RasterTriangle, layer), MEMBER(RasterTriangle, material),
               MEMBER(RasterTriangle, origin), MEMBER(RasterTriangle, alphaTested),
               MEMBER(RasterTriangle, firstEntry), MEMBER(RasterTriangle, depthPlane),
               MEMBER(RasterTriangle, depthBias), MEMBER(RasterTriangle, uOverW), MEMBER(RasterTriangle, pad0),
               MEMBER(RasterTriangle, vOverW), MEMBER(RasterTriangle, pad1), MEMBER(RasterTriangle, invW),
               MEMBER(RasterTriangle, pad2), MEMBER(RasterTriangle, visibilityId),
               MEMBER(RasterTriangle, idLayerPlusOne), MEMBER(RasterTriangle, pad3), MEMBER(RasterTriangle, pad4)),
        STRUCT(RasterLayer, MEMBER(RasterLayer, viewRow), MEMBER(RasterLayer, targetLayer),
               MEMBER(RasterLayer, skipBlended), MEMBER(RasterLayer, idLayerPlusOne)),
        STRUCT(RasterPush, MEMBER(RasterPush, width), MEMBER(RasterPush, subpixelBits),
               MEMBER(RasterPush, triangleCount), MEMBER(RasterPush, layerCount), MEMBER(RasterPush, recordCapacity),
               MEMBER(RasterPush, entryCapacity), MEMBER(RasterPush, smallExtent), MEMBER(RasterPush, height),
               MEMBER(RasterPush, biasConstant), MEMBER(RasterPush, biasSlope),
               MEMBER(RasterPush, frontsCounterClockwise), MEMBER(RasterPush, pad0)),
        STRUCT(RasterCounters, MEMBER(RasterCounters, records), MEMBER(RasterCounters, tileEntries),
               MEMBER(RasterCounters, inlined), MEMBER(RasterCounters, placed)),
    };
    return table;
}

// ---- The SPIR-V side ----
struct ReflectedBinding {
    uint32_t set, binding;
    VkDescriptorType type;
    uint32_t count;  // 0: a runtime-sized array
    std::string name;
};
struct ReflectedStruct {
    std::string name;
    size_t size;
    std::vector<MemberLayout> members;
};
struct ReflectedModule {
    std::vector<ReflectedBinding> bindings;
    size_t pushBytes = 0;
    std::vector<ReflectedStruct> structs;  // every struct type reachable from a block, by name
};

class Reflector {
public:
    Reflector() { spvc_context_create(&context_); }
    ~Reflector() { spvc_context_destroy(context_); }
    Reflector(const Reflector&) = delete;
    Reflector& operator=(const Reflector&) = delete;

    ReflectedModule reflect(const vk::EmbeddedShader& shader) {
        return reflect(shader.key, reinterpret_cast<const SpvId*>(shader.code), shader.size / 4);
    }

    ReflectedModule reflect(const std::string& key, const SpvId* words, size_t wordCount) {
        ReflectedModule out;
        spvc_parsed_ir ir = nullptr;
        spvc_compiler compiler = nullptr;
        spvc_resources resources = nullptr;
        if (spvc_context_parse_spirv(context_, words, wordCount, &ir) != SPVC_SUCCESS ||
            spvc_context_create_compiler(context_, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                         &compiler) != SPVC_SUCCESS ||
            spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS) {
            ADD_FAILURE() << key << ": " << spvc_context_get_last_error_string(context_);
            return out;
        }
        compiler_ = compiler;
        const std::pair<spvc_resource_type, VkDescriptorType> kinds[] = {
            {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
            {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
            {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
            {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
            {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE},
            {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, VK_DESCRIPTOR_TYPE_SAMPLER},
        };
        for (const auto& [kind, type] : kinds) {
            for (const spvc_reflected_resource& r : list(resources, kind)) {
                const uint32_t set = spvc_compiler_get_decoration(compiler, r.id, SpvDecorationDescriptorSet);
                const uint32_t binding = spvc_compiler_get_decoration(compiler, r.id, SpvDecorationBinding);
                out.bindings.push_back({set, binding, type, arraySize(r.type_id), r.name ? r.name : ""});
                if (kind == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER || kind == SPVC_RESOURCE_TYPE_STORAGE_BUFFER)
                    collectStructs(r.base_type_id, out.structs, false);
            }
        }
        for (const spvc_reflected_resource& r : list(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT)) {
            spvc_compiler_get_declared_struct_size(compiler, spvc_compiler_get_type_handle(compiler, r.base_type_id),
                                                   &out.pushBytes);
            collectStructs(r.base_type_id, out.structs, false);
        }
        return out;
    }

private:
    std::vector<spvc_reflected_resource> list(spvc_resources resources, spvc_resource_type kind) {
        const spvc_reflected_resource* items = nullptr;
        size_t n = 0;
        spvc_resources_get_resource_list_for_type(resources, kind, &items, &n);
        return {items, items + n};
    }

    uint32_t arraySize(spvc_type_id id) {
        spvc_type type = spvc_compiler_get_type_handle(compiler_, id);
        uint32_t count = 1;
        for (unsigned d = 0; d < spvc_type_get_num_array_dimensions(type); ++d)
            count *= spvc_type_array_dimension_is_literal(type, d) ? spvc_type_get_array_dimension(type, d) : 0;
        return count;
    }

    // The struct `id` (a block's own struct is not a shared struct: `isShared` is false for it) and
    // every struct among its members, recursively.
    void collectStructs(spvc_type_id id, std::vector<ReflectedStruct>& out, bool isShared = true) {
        spvc_type type = spvc_compiler_get_type_handle(compiler_, id);
        const spvc_type_id base = spvc_type_get_base_type_id(type);
        spvc_type structType = spvc_compiler_get_type_handle(compiler_, base);
        if (spvc_type_get_basetype(structType) != SPVC_BASETYPE_STRUCT) return;
        ReflectedStruct s{spvc_compiler_get_name(compiler_, base), 0, {}};
        spvc_compiler_get_declared_struct_size(compiler_, structType, &s.size);
        for (unsigned i = 0; i < spvc_type_get_num_member_types(structType); ++i) {
            unsigned offset = 0;
            spvc_compiler_type_struct_member_offset(compiler_, structType, i, &offset);
            s.members.push_back({spvc_compiler_get_member_name(compiler_, base, i), offset});
            collectStructs(spvc_type_get_member_type(structType, i), out);
        }
        if (isShared) out.push_back(std::move(s));
    }

    spvc_context context_ = nullptr;
    spvc_compiler compiler_ = nullptr;
};

// ---- Which pipelines the C++ declares: the renderer built for settings that reach every shader ----
struct Configuration {
    const char* scene;
    void (*apply)(RenderSettings&);
    bool blended = false;  // the scene's first material alphaMode BLEND (no built-in scene has one)
};

std::vector<Configuration> configurations() {
    return {
        {"cornell", [](RenderSettings& s) { s.gi = GiMode::Rsm; s.shadow.filter = ShadowFilter::Pcf; }},
        {"cornell",
         [](RenderSettings& s) {
             s.gi = GiMode::Rsm;
             s.rsm.far = RsmFar::Disc;
             s.rsm.radii = RsmRadii::Fixed;
             s.rsm.visibility = RsmVisibility::Voxels;
             s.giTemporal = true;
             s.cameraPath = CameraPath::Gbuffer;
             s.shadow.filter = ShadowFilter::Pcss;
         }},
        {"cornell",
         [](RenderSettings& s) {
             s.gi = GiMode::Rsm;
             s.rsm.far = RsmFar::Disc;
             s.rsm.radii = RsmRadii::Fixed;
             s.rsm.visibility = RsmVisibility::Depth;
             s.shadow.filter = ShadowFilter::Vsm;
             s.aov = Aov::RsmFlux;
         }},
        {"cornell", [](RenderSettings& s) { s.gi = GiMode::Lpv; s.shadow.filter = ShadowFilter::Msm; }},
        {"cornell",
         [](RenderSettings& s) {
             s.gi = GiMode::Lpv;
             s.lpv.geometry = LpvGeometry::Voxels;
             s.shadow.filter = ShadowFilter::Evsm;
             s.shadow.raster = RasterMode::Compute;
         }},
        {"street", [](RenderSettings& s) { s.gi = GiMode::Lpv; s.lighting.sky.kind = SkyKind::Analytic; }},
        {"room", [](RenderSettings& s) { s.shadow.pointMode = PointShadowMode::Paraboloid; }},
        {"room", [](RenderSettings& s) { s.shadow.raster = RasterMode::Compute; s.aov = Aov::ShadowMap; }},
        {"hair", [](RenderSettings& s) { s.dsm.enabled = true; }},
        {"hair", [](RenderSettings& s) { s.dsm.enabled = true; s.dsm.opacityMaps = true; s.cameraPath = CameraPath::Gbuffer; }},
        {"hair", [](RenderSettings& s) { s.dsm.enabled = true; s.shadow.raster = RasterMode::Compute; }},
        {"hair", [](RenderSettings& s) { s.dsm.enabled = true; s.translucency = false; }},
        {"cornell", [](RenderSettings& s) { s.dsm.enabled = true; }, true},
    };
}

class SpirvReflectionTest : public GpuTest {};

std::string describe(VkDescriptorType type) {
    switch (type) {
        case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "uniform buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "storage buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "storage image";
        case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "combined image sampler";
        case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return "sampled image";
        case VK_DESCRIPTOR_TYPE_SAMPLER: return "sampler";
        default: return "descriptor type " + std::to_string(int(type));
    }
}

// Checks one module against one pipeline's declaration; returns the failures, one line each.
std::vector<std::string> compare(const std::string& key, const ReflectedModule& module,
                                 const vk::PipelineInterface& declared) {
    std::vector<std::string> errors;
    for (const ReflectedBinding& b : module.bindings) {
        const vk::Binding* match = nullptr;
        if (b.set < declared.sets.size())
            for (const vk::Binding& d : declared.sets[b.set])
                if (d.binding == b.binding) match = &d;
        if (!match) {
            errors.push_back(key + ": set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) + " (" +
                             b.name + ") is not declared by its pipeline");
            continue;
        }
        if (match->type != b.type)
            errors.push_back(key + ": binding " + std::to_string(b.binding) + " (" + b.name + ") is type " +
                             describe(b.type) + " in the shader, " + describe(match->type) + " in C++");
        if (b.count != 0 && match->count != b.count)
            errors.push_back(key + ": binding " + std::to_string(b.binding) + " (" + b.name + ") has " +
                             std::to_string(b.count) + " elements in the shader, " + std::to_string(match->count) +
                             " in C++");
    }
    if (module.pushBytes > declared.pushBytes)
        errors.push_back(key + ": " + std::to_string(module.pushBytes) + " push-constant bytes in the shader, " +
                         std::to_string(declared.pushBytes) + " declared");
    return errors;
}

// Every binding of every embedded module agrees with the C++ declaration of each pipeline that uses
// it, and every module is used by some pipeline of the configurations. Each renderer's pipelines
// are checked before it records a frame: a mismatch is named here before it can crash a driver.
TEST_F(SpirvReflectionTest, EveryModuleMatchesItsPipelineDeclarations) {
    Reflector reflector;
    std::map<std::string, ReflectedModule> modules;
    for (const vk::EmbeddedShader* s = vk::kEmbeddedShaders; s->key; ++s) modules[s->key] = reflector.reflect(*s);
    std::set<std::string> used;
    size_t checkedPipelines = 0, checkedBindings = 0;
    const auto checkNewPipelines = [&] {
        const std::vector<vk::PipelineInterface>& declared = vk::declaredInterfaces(ctx());
        for (; checkedPipelines < declared.size(); ++checkedPipelines) {
            for (const std::string& shader : declared[checkedPipelines].shaders) {
                auto it = modules.find(shader);
                if (it == modules.end()) continue;  // findShader throws for an unknown key first
                used.insert(shader);
                for (const std::string& e : compare(shader, it->second, declared[checkedPipelines])) ADD_FAILURE() << e;
                checkedBindings += it->second.bindings.size();
            }
        }
    };
    for (const Configuration& c : configurations()) {
        RenderSettings s;
        s.width = 64;
        s.height = 48;
        s.shadow.resolution = 256;
        s.rsm.resolution = 64;
        s.lpv.rsmResolution = 64;
        s.lpv.vplResolution = 16;
        s.lpv.resolution = 16;
        c.apply(s);
        BuiltinOptions options;
        options.hairStrands = 100;
        Scene scene = makeBuiltinScene(c.scene, options);
        if (c.blended) {
            scene.materials[0].alphaMode = AlphaMode::Blend;
            scene.materials[0].baseColor.a = 0.5f;
        }
        Renderer renderer(ctx(), scene, s);
        checkNewPipelines();
        ASSERT_FALSE(HasFailure()) << "a pipeline's declaration disagrees with its shader: no frame recorded";
        renderer.render(scene.cameras[0]);  // pipelines made on the first frame (shadow layouts)
        checkNewPipelines();
    }
    for (const auto& [key, module] : modules)
        EXPECT_TRUE(used.count(key)) << key << ": no pipeline of the test's configurations uses it";
    EXPECT_GT(modules.size(), 50u);
    EXPECT_GT(checkedBindings, 300u);
    std::printf("[ reflect  ] %zu modules, %zu pipeline declarations, %zu bindings compared\n", modules.size(),
                checkedPipelines, checkedBindings);
}

// Every struct the shaders see under a shared name has the C++ struct's size and, member by member,
// its names and offsets; every struct of shared/types.h is seen by some module.
TEST(SpirvReflection, SharedStructsMatchTheCppLayouts) {
    Reflector reflector;
    std::set<std::string> seen;
    size_t compared = 0;
    for (const vk::EmbeddedShader* s = vk::kEmbeddedShaders; s->key; ++s) {
        // The embedded module's twin compiled with its names (tests/CMakeLists.txt).
        std::ifstream file(std::string(PENUMBRA_REFLECT_DIR) + "/" + s->key + ".spv", std::ios::binary);
        ASSERT_TRUE(file) << s->key << ": no unoptimised copy";
        const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        std::vector<SpvId> words(bytes.size() / 4);
        std::memcpy(words.data(), bytes.data(), words.size() * 4);
        for (const ReflectedStruct& r : reflector.reflect(s->key, words.data(), words.size()).structs) {
            auto it = sharedStructs().find(r.name);
            if (it == sharedStructs().end()) continue;  // a shader's own struct
            seen.insert(r.name);
            const StructLayout& cpp = it->second;
            EXPECT_EQ(r.size, cpp.size) << s->key << ": sizeof " << r.name;
            ASSERT_EQ(r.members.size(), cpp.members.size()) << s->key << ": members of " << r.name;
            for (size_t i = 0; i < r.members.size(); ++i) {
                EXPECT_EQ(r.members[i].name, cpp.members[i].name) << s->key << ": " << r.name << " member " << i;
                EXPECT_EQ(r.members[i].offset, cpp.members[i].offset)
                    << s->key << ": offset of " << r.name << "." << r.members[i].name;
                ++compared;
            }
        }
    }
    for (const auto& [name, layout] : sharedStructs()) EXPECT_TRUE(seen.count(name)) << name << " seen by no shader";
    // Every struct of shared/types.h and of the modules' types.h has its row above.
    const std::regex declaration(R"(\nstruct (\w+) \{)");
    size_t declared = 0;
    for (const char* header : {"shared", "shadow", "dsm", "raster", "voxel"}) {
        std::ifstream types(std::string(PENUMBRA_SOURCE_DIR) + "/shaders/" + header + "/types.h");
        ASSERT_TRUE(types) << header << "/types.h";
        const std::string text((std::istreambuf_iterator<char>(types)), std::istreambuf_iterator<char>());
        for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it) {
            const std::string name = (*it)[1];
            ++declared;
            EXPECT_TRUE(sharedStructs().count(name))
                << header << "/types.h declares " << name << ", which has no row here";
        }
    }
    EXPECT_EQ(declared, sharedStructs().size());
    EXPECT_GT(compared, 500u);
    std::printf("[ reflect  ] %zu shared structs, %zu members compared\n", seen.size(), compared);
}

}  // namespace
}  // namespace penumbra::test
