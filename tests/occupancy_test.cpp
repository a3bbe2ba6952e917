// The occupancy volume (src/voxel) against a brute-force voxelization on the CPU in double precision:
// every voxel that a triangle meets (separating-axis test), and no other.
#include <array>
#include <cmath>
#include <random>

#include "gpu_fixture.h"
#include "readback.h"
#include "scene/builders.h"
#include "voxel/occupancy_volume.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

using Tri = std::array<glm::dvec3, 3>;

// Whether triangle t meets the axis-aligned box of centre c and half size h (Akenine-Moller 2001:
// the box's axes, the triangle's normal, the nine edge x axis cross products); touching meets.
bool triangleMeetsBox(const Tri& t, const glm::dvec3& c, double h) {
    const Tri v{t[0] - c, t[1] - c, t[2] - c};
    for (int a = 0; a < 3; ++a) {
        const double lo = std::min({v[0][a], v[1][a], v[2][a]}), hi = std::max({v[0][a], v[1][a], v[2][a]});
        if (lo > h || hi < -h) return false;
    }
    const glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    if (std::abs(glm::dot(n, v[0])) > h * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z))) return false;
    for (int e = 0; e < 3; ++e) {
        const glm::dvec3 edge = v[(e + 1) % 3] - v[e];
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 unit(0.0);
            unit[a] = 1.0;
            const glm::dvec3 axis = glm::cross(unit, edge);
            const double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
            const double r = h * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
            if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
        }
    }
    return true;
}

// One draw per triangle: the brute force reads each draw's first triangle.
void addTriangle(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
    const Vertex corners[3] = {{a, {0, 0, 1}, {0, 0}}, {b, {0, 0, 1}, {0, 0}}, {c, {0, 0, 1}, {0, 0}}};
    const uint32_t order[3] = {0, 1, 2};
    addTriangles(s, corners, order, material, false);
}

// Triangles of every size in a 2 m box: ordinary, slivers, tiny (inside one voxel), walls larger
// than a workgroup's columns, axis-aligned ones, zero-area ones (they occupy nothing), and one
// blended (it lets light through: it occupies nothing either).
Scene randomTriangles(uint32_t seed) {
    Scene s;
    Material opaque, blended;
    blended.alphaMode = AlphaMode::Blend;
    s.materials = {opaque, blended};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), small(-0.01f, 0.01f);
    auto point = [&] { return glm::vec3(u(rng), u(rng), u(rng)); };
    for (int i = 0; i < 60; ++i) {
        const glm::vec3 a = point();
        switch (i % 5) {
            case 0: addTriangle(s, a, point(), point(), 0); break;
            case 1: addTriangle(s, a, a + glm::vec3(small(rng), small(rng), small(rng)), point(), 0); break;
            case 2: addTriangle(s, a, a + glm::vec3(small(rng), 0.02f, 0), a + glm::vec3(0.02f, small(rng), 0), 0); break;
            case 3: addTriangle(s, a, {a.x, u(rng), u(rng)}, {a.x, u(rng), u(rng)}, 0); break;  // in a plane x = const
            default: addTriangle(s, a, a, point(), 0); break;  // zero area
        }
    }
    addTriangle(s, {-1, -1, -1}, {1, -1, -1}, {1, 1, 1}, 0);  // larger than any workgroup's share
    addTriangle(s, {-1, 0.3f, -1}, {1, 0.3f, -1}, {-1, 0.3f, 1}, 1);
    s.computeBounds();
    return s;
}

}  // namespace

TEST(OccupancyGrid, CubicVoxelsWithAMarginAroundTheBoundsInWholeBricks) {
    Bounds b;
    b.extend({-2, 0, 1});
    b.extend({6, 1, 3});
    const gpu::GpuOccupancyGrid g = occupancyGrid(b, 34);
    EXPECT_FLOAT_EQ(g.voxelSize, 8.0f / 32.0f);
    EXPECT_EQ(g.dims.x, 36u);  // 34 rounded up to bricks of 4
    EXPECT_EQ(g.dims.y, 8u);   // ceil(1 / 0.25) + 2 = 6, rounded up
    EXPECT_EQ(g.dims.z, 12u);  // ceil(2 / 0.25) + 2 = 10, rounded up
    EXPECT_EQ(g.firstBrickWord, 36u * 8u * 12u / 32u) << "the brick bits follow the voxels' words";
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(g.origin[a] + g.voxelSize, b.min[a] + 1e-5f) << "axis " << a;
        EXPECT_GE(g.origin[a] + g.voxelSize * (float(g.dims[a]) - 1.0f), b.max[a] - 1e-5f) << "axis " << a;
    }
}

class OccupancyTest : public GpuTest {};

// The occupancy volume of `scene` at `resolution`, built on the GPU and read back whole.
struct BuiltVolume {
    gpu::GpuOccupancyGrid grid;
    std::vector<uint8_t> bytes;
};

BuiltVolume buildVolume(vk::Context& ctx, const Scene& scene, uint32_t resolution) {
    vk::Allocator alloc(ctx);
    vk::CommandContext cmd(alloc);
    SceneGpu meshes(cmd, scene);
    OccupancyVolume volume(alloc, meshes, resolution);
    FrameGraph graph(ctx);
    volume.addTo(graph);
    cmd.submitAndWait([&](VkCommandBuffer c) { graph.execute(c, nullptr); });
    return {volume.grid(), cmd.readBuffer(volume.buffer(), volume.buffer().size())};
}

TEST_F(OccupancyTest, VoxelsAreExactlyThoseTheTrianglesMeet) {
    for (uint32_t seed : {1u, 2u, 3u}) {
        Scene scene = randomTriangles(seed);
        const BuiltVolume built = buildVolume(ctx(), scene, 40);
        const gpu::GpuOccupancyGrid& g = built.grid;
        const std::vector<uint8_t>& bytes = built.bytes;
        const size_t voxels = size_t(g.dims.x) * g.dims.y * g.dims.z;
        gpu::GpuOccupancyGrid header;
        std::memcpy(&header, bytes.data(), sizeof(header));
        EXPECT_EQ(header.dims, g.dims);
        auto gpuBit = [&](size_t i) { return (u32(bytes, sizeof(header) / 4 + i / 32) >> (i % 32)) & 1u; };

        // Each voxel the triangles meet with margin to spare (the box shrunk by 1e-3 voxel) must be set;
        // none they miss by as much (the box grown by 1e-3) may be. Between the two lie the voxels a
        // triangle only touches, where float and double may disagree.
        std::vector<uint8_t> surely(voxels, 0), maybe(voxels, 0);
        const double size = g.voxelSize, half = 0.5 * size, slack = 1e-3 * size;
        for (const Draw& d : scene.draws) {
            if (scene.materials[d.material].alphaMode == AlphaMode::Blend) continue;
            Tri t;
            for (int k = 0; k < 3; ++k) t[k] = glm::dvec3(scene.vertices[scene.indices[d.firstIndex + k]].position);
            if (glm::length(glm::cross(t[1] - t[0], t[2] - t[0])) == 0.0) continue;  // zero area: nothing
            for (uint32_t z = 0; z < g.dims.z; ++z)
                for (uint32_t y = 0; y < g.dims.y; ++y)
                    for (uint32_t x = 0; x < g.dims.x; ++x) {
                        const glm::dvec3 c = glm::dvec3(g.origin) + size * (glm::dvec3(x, y, z) + 0.5);
                        const size_t i = x + g.dims.x * (y + size_t(g.dims.y) * z);
                        surely[i] |= triangleMeetsBox(t, c, half - slack);
                        maybe[i] |= triangleMeetsBox(t, c, half + slack);
                    }
        }
        size_t set = 0, touched = 0, missing = 0, extra = 0;
        for (size_t i = 0; i < voxels; ++i) {
            set += surely[i];
            touched += maybe[i] && !surely[i];
            missing += surely[i] && !gpuBit(i);
            extra += !maybe[i] && gpuBit(i);
        }
        // A brick's bit is set exactly where one of its voxels is.
        size_t brickErrors = 0, bricksSet = 0;
        const glm::uvec3 bricks = glm::uvec3(g.dims) / uint32_t(OCCUPANCY_BRICK);
        for (uint32_t b = 0; b < bricks.x * bricks.y * bricks.z; ++b) {
            const glm::uvec3 c(b % bricks.x, (b / bricks.x) % bricks.y, b / (bricks.x * bricks.y));
            uint32_t any = 0;
            for (uint32_t k = 0; k < 64; ++k) {
                const glm::uvec3 v = c * 4u + glm::uvec3(k % 4, (k / 4) % 4, k / 16);
                any |= gpuBit(v.x + g.dims.x * (v.y + size_t(g.dims.y) * v.z));
            }
            const uint32_t bit = (u32(bytes, sizeof(header) / 4 + g.firstBrickWord + b / 32) >> (b % 32)) & 1u;
            brickErrors += bit != any;
            bricksSet += bit;
        }
        EXPECT_EQ(brickErrors, 0u) << "seed " << seed << ": " << bricksSet << " bricks set";
        std::printf("[ occupancy ] seed %u: %ux%ux%u voxels, %zu met, %zu touched, %zu missing, %zu extra\n", seed,
                    g.dims.x, g.dims.y, g.dims.z, set, touched, missing, extra);
        EXPECT_GT(set, 2000u);
        EXPECT_EQ(missing, 0u) << "seed " << seed;
        EXPECT_EQ(extra, 0u) << "seed " << seed;
    }
}


// The sky's facing bits (voxel/types.h) against the same brute force: a voxel blocks quadrant q of the
// upward rays where a triangle meeting it is double-sided or faces the quadrant's middle direction
// (+-1, 1, +-1); the random triangles are single-sided, one wall in four double-sided here.
TEST_F(OccupancyTest, SkyFacingBitsAreThoseOfTheTrianglesThatMeetTheVoxel) {
    for (uint32_t seed : {4u, 5u}) {
        Scene scene = randomTriangles(seed);
        Material twoSided;
        twoSided.doubleSided = true;
        scene.materials.push_back(twoSided);
        for (size_t k = 0; k < scene.draws.size(); k += 4)
            if (scene.draws[k].material == 0) scene.draws[k].material = uint32_t(scene.materials.size() - 1);
        ASSERT_TRUE(hasSingleSidedSurfaces(scene));
        const BuiltVolume built = buildVolume(ctx(), scene, 40);
        const gpu::GpuOccupancyGrid& g = built.grid;
        const std::vector<uint8_t>& bytes = built.bytes;
        const size_t voxels = size_t(g.dims.x) * g.dims.y * g.dims.z;
        ASSERT_GT(g.skyFirstWord, g.firstBrickWord);
        EXPECT_EQ(bytes.size(), OccupancyVolume::bytes(scene.bounds, 40, true));
        const size_t header = sizeof(gpu::GpuOccupancyGrid) / 4;
        auto gpuFacing = [&](size_t i) { return (u32(bytes, header + g.skyFirstWord + i / 8) >> (4 * (i % 8))) & 0xFu; };

        std::vector<uint8_t> surely(voxels, 0), maybe(voxels, 0);  // facing bits, as in the test above
        const double size = g.voxelSize, half = 0.5 * size, slack = 1e-3 * size;
        for (const Draw& d : scene.draws) {
            const Material& m = scene.materials[d.material];
            if (m.alphaMode == AlphaMode::Blend) continue;
            Tri t;
            for (int k = 0; k < 3; ++k) t[k] = glm::dvec3(scene.vertices[scene.indices[d.firstIndex + k]].position);
            const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
            if (glm::length(n) == 0.0) continue;
            uint8_t facing = 0;
            for (uint32_t q = 0; q < 4; ++q)
                if (m.doubleSided || glm::dot(n, glm::dvec3(q & 1 ? 1 : -1, 1, q & 2 ? 1 : -1)) > 0.0) facing |= 1 << q;
            for (uint32_t z = 0; z < g.dims.z; ++z)
                for (uint32_t y = 0; y < g.dims.y; ++y)
                    for (uint32_t x = 0; x < g.dims.x; ++x) {
                        const glm::dvec3 c = glm::dvec3(g.origin) + size * (glm::dvec3(x, y, z) + 0.5);
                        const size_t i = x + g.dims.x * (y + size_t(g.dims.y) * z);
                        if (triangleMeetsBox(t, c, half - slack)) surely[i] |= facing;
                        if (triangleMeetsBox(t, c, half + slack)) maybe[i] |= facing;
                    }
        }
        size_t missing = 0, extra = 0, partial = 0;
        for (size_t i = 0; i < voxels; ++i) {
            const uint32_t bits = gpuFacing(i);
            missing += (surely[i] & ~bits) != 0;
            extra += (bits & ~maybe[i]) != 0;
            partial += bits != 0 && bits != 0xFu;
        }
        std::printf("[ occupancy ] seed %u: %zu voxels block some quadrants but not all\n", seed, partial);
        EXPECT_GT(partial, 500u) << "single-sided triangles leave some quadrants open";
        EXPECT_EQ(missing, 0u) << "seed " << seed;
        EXPECT_EQ(extra, 0u) << "seed " << seed;
    }
}
