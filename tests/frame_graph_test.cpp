// The frame graph's schedule (core/frame_graph.h): which passes run together, and that a graph run
// in its groups gives the results of its passes in order, with the synchronization validation layer
// silent (a missing barrier between dependent passes would be a reported hazard).
#include <cstring>

#include "gpu_fixture.h"
#include "core/frame_graph.h"
#include "vk/commands.h"
#include "vk/memory.h"
#include "vk/resources.h"

namespace penumbra::test {
namespace {

using Groups = std::vector<std::vector<uint32_t>>;

class FrameGraphTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        alloc_ = std::make_unique<vk::Allocator>(ctx());
    }
    void TearDown() override {
        buffers_.clear();
        images_.clear();
        alloc_.reset();
        GpuTest::TearDown();
    }
    const vk::Buffer& buffer(const char* name) {
        const VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        return *buffers_.emplace_back(std::make_unique<vk::Buffer>(*alloc_, 256, usage, false, name));
    }
    vk::Image& image(const char* name) {
        vk::ImageDesc d;
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        d.name = name;
        return *images_.emplace_back(std::make_unique<vk::Image>(*alloc_, d));
    }
    // A compute pass that only declares its uses (its record does nothing).
    static void declare(FrameGraph& g, const char* name, std::vector<std::pair<BufferHandle, Use>> uses,
                        std::vector<std::pair<ImageHandle, Use>> imageUses = {}) {
        PassBuilder p = g.pass(name, PassKind::Compute);
        for (auto [h, u] : uses) p.use(h, u);
        for (auto [h, u] : imageUses) p.use(h, u);
        p.record([](PassContext&) {});
    }
    std::unique_ptr<vk::Allocator> alloc_;
    std::vector<std::unique_ptr<vk::Buffer>> buffers_;
    std::vector<std::unique_ptr<vk::Image>> images_;
};

// Two chains that share nothing run side by side, a step of each per group; a pass that reads both
// chains' ends waits for both.
TEST_F(FrameGraphTest, IndependentChainsRunTogether) {
    FrameGraph g(ctx());
    const BufferHandle a = g.import(buffer("a")), b = g.import(buffer("b")), c = g.import(buffer("c")),
                       d = g.import(buffer("d")), e = g.import(buffer("e"));
    declare(g, "a.write", {{a, Use::StorageWrite}});
    declare(g, "a.to-b", {{a, Use::StorageRead}, {b, Use::StorageWrite}});
    declare(g, "c.write", {{c, Use::StorageWrite}});
    declare(g, "c.to-d", {{c, Use::StorageRead}, {d, Use::StorageWrite}});
    declare(g, "b-d.to-e", {{b, Use::StorageRead}, {d, Use::StorageRead}, {e, Use::StorageWrite}});
    EXPECT_EQ(g.schedule(), (Groups{{0, 2}, {1, 3}, {4}}));
    g.setOverlap(false);
    EXPECT_EQ(g.schedule(), (Groups{{0}, {1}, {2}, {3}, {4}}));
}

// Readers of one buffer run together; a later writer waits for all of them (write after read), and
// a reader after it waits for it.
TEST_F(FrameGraphTest, WriterWaitsForTheReadersBeforeIt) {
    FrameGraph g(ctx());
    const BufferHandle x = g.import(buffer("x")), y = g.import(buffer("y")), z = g.import(buffer("z"));
    declare(g, "x.write", {{x, Use::StorageWrite}});
    declare(g, "x.read-1", {{x, Use::StorageRead}, {y, Use::StorageWrite}});
    declare(g, "x.read-2", {{x, Use::Uniform}, {z, Use::StorageWrite}});
    declare(g, "x.rewrite", {{x, Use::TransferDst}});
    declare(g, "x.read-3", {{x, Use::IndirectArgs}});
    declare(g, "unrelated", {{g.import(buffer("w")), Use::StorageWrite}});
    EXPECT_EQ(g.schedule(), (Groups{{0, 5}, {1, 2}, {3}, {4}}));
}

// An image read in two layouts (sampled, then as a storage image) is a layout change between the
// reads: the second waits for the first. Two sampled reads share a group. A pass that uses one
// buffer twice (storage and indirect arguments) does not wait for itself.
TEST_F(FrameGraphTest, LayoutChangesOrderReadsOfAnImage) {
    FrameGraph g(ctx());
    const ImageHandle img = g.import(image("img"));
    const BufferHandle args = g.import(buffer("args"));
    declare(g, "img.write", {}, {{img, Use::StorageWrite}});
    declare(g, "img.sample-1", {}, {{img, Use::Sampled}});
    declare(g, "img.sample-2", {{args, Use::StorageWrite}, {args, Use::IndirectArgs}}, {{img, Use::Sampled}});
    declare(g, "img.storage-read", {}, {{img, Use::StorageRead}});
    EXPECT_EQ(g.schedule(), (Groups{{0}, {1, 2}, {3}}));
}

// Executed in its groups, with real transfers: the results are those of the passes in the order
// added, and the synchronization validation layer (GpuTest) reports no hazard.
TEST_F(FrameGraphTest, GroupedExecutionGivesTheResultsInOrder) {
    const vk::Buffer &a = buffer("a"), &b = buffer("b"), &c = buffer("c"), &d = buffer("d");
    vk::CommandContext cmd(*alloc_);
    for (bool overlap : {true, false}) {
        FrameGraph g(ctx());
        g.setOverlap(overlap);
        const BufferHandle ha = g.import(a), hb = g.import(b), hc = g.import(c), hd = g.import(d);
        auto fill = [&](const char* name, BufferHandle h, uint32_t value) {
            g.pass(name, PassKind::Transfer).use(h, Use::TransferDst).record([h, value](PassContext& p) {
                vkCmdFillBuffer(p.cmd, p.buffer(h).handle(), 0, VK_WHOLE_SIZE, value);
            });
        };
        auto copy = [&](const char* name, BufferHandle from, BufferHandle to) {
            g.pass(name, PassKind::Transfer)
                .use(from, Use::TransferSrc)
                .use(to, Use::TransferDst)
                .record([from, to](PassContext& p) {
                    VkBufferCopy region{0, 0, 256};
                    vkCmdCopyBuffer(p.cmd, p.buffer(from).handle(), p.buffer(to).handle(), 1, &region);
                });
        };
        fill("a.fill", ha, overlap ? 1u : 5u);
        copy("a.to-b", ha, hb);
        fill("c.fill", hc, overlap ? 2u : 6u);
        copy("c.to-d", hc, hd);
        fill("a.refill", ha, 3u);  // after a.to-b read it
        copy("d.to-a", hd, ha);    // after a.refill wrote it
        if (overlap) {
            EXPECT_EQ(g.schedule(), (Groups{{0, 2}, {1, 3}, {4}, {5}}));
        }
        cmd.submitAndWait([&](VkCommandBuffer c) { g.execute(c, nullptr); });
        auto first = [&](const vk::Buffer& buf) {
            uint32_t v = 0;
            std::memcpy(&v, cmd.readBuffer(buf, 4).data(), 4);
            return v;
        };
        EXPECT_EQ(first(b), overlap ? 1u : 5u);
        EXPECT_EQ(first(d), overlap ? 2u : 6u);
        EXPECT_EQ(first(a), overlap ? 2u : 6u);
    }
}

}  // namespace
}  // namespace penumbra::test
