// Option fuzzer generated from the CLI itself: every option of every subcommand, walked on the CLI11
// App (so options added later, and the viewer's `set OPTION VALUE` over the same definitions, are
// covered), is given -1, 0, huge, NaN, infinity and text, in-process and in dry-run mode (options,
// paths and the scene are checked; no GPU work). Each run must end in a CLI11 parse error or an
// exception with a one-line message, or succeed; a numeric option must never accept NaN, infinity
// or text. And the `compare` command's EXR input, truncated and mutated.
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli_app.h"
#include "eval/compare.h"
#include "gltf_test_util.h"
#include "io/image_io.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

enum class Result { ParseError, RunError, Ok };

// Parses and (dry-)runs one command line; any other outcome than the contract fails the test.
Result runCli(const std::vector<std::string>& args, std::string& message) {
    Cli cli("penumbra fuzz");
    cli.dryRun = true;
    std::vector<const char*> argv{"penumbra"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    try {
        cli.app.parse(int(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
        message = e.what();
        return Result::ParseError;
    }
    try {
        cli.run();
    } catch (const std::exception& e) {
        message = e.what();
        return Result::RunError;
    }
    return Result::Ok;
}

struct Command {
    std::string name;
    std::vector<std::string> base;  // the positional arguments and outputs it needs
};

}  // namespace

TEST(OptionFuzz, EveryOptionWithOddValuesEndsInOneErrorLineOrRuns) {
    TempDir dir;
    const std::vector<float> pixels(16 * 4, 0.5f);
    writeExr(dir.file("a.exr"), 4, 4, pixels);
    const std::vector<Command> commands{
        {"render", {"render", "cornell", "-o", dir.file("out.png")}},
        {"bench", {"bench", "cornell"}},
        {"reference", {"reference", "cornell", "-o", dir.file("ref.exr")}},
        {"eval", {"eval", "cornell"}},
        {"compare", {"compare", dir.file("a.exr"), dir.file("a.exr")}},
    };
    const std::vector<std::string> values{"-1", "0", "1", "65537", "99999999999", "1e30", "nan", "NaN", "inf",
                                          "-inf", "text", "", "1,2", "0x10"};
    int runs = 0, errors = 0, options = 0;
    const Cli walker;
    for (const Command& c : commands) {
        const CLI::App* sub = walker.app.get_subcommand(c.name);
        for (const CLI::Option* opt : sub->get_options()) {
            if (opt->get_positional() || opt->get_type_size() == 0 || opt->get_lnames().empty()) continue;  // flags
            const std::string name = "--" + opt->get_lnames().front();
            const std::string type = opt->get_type_name();
            const bool numeric = type.rfind("FLOAT", 0) == 0 || type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0;
            ++options;
            for (const std::string& value : values) {
                std::vector<std::string> args = c.base;
                args.insert(args.end(), {name, value});
                std::string message;
                const Result r = runCli(args, message);
                ++runs;
                SCOPED_TRACE(c.name + " " + name + " '" + value + "' (" + type + ")");
                if (r == Result::Ok) {
                    const bool bad = value == "nan" || value == "NaN" || value == "inf" || value == "-inf" ||
                                     value == "text" || value == "";
                    EXPECT_FALSE(numeric && bad) << "a numeric option accepted it";
                    continue;
                }
                ++errors;
                EXPECT_FALSE(message.empty());
                EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            }
        }
    }
    EXPECT_GT(options, 80);  // every subcommand's options were walked
    std::printf("option fuzz: %d options, %d runs, %d ended in an error line\n", options, runs, errors);
}

// `compare` reads its inputs with readExrChecked: truncated and mutated EXR files must give one line.
TEST(ExrFuzz, TruncatedAndMutatedInputsGiveOneErrorLine) {
    TempDir dir;
    std::vector<float> pixels(8 * 6 * 4);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 17) * 0.1f;
    const std::string good = dir.file("good.exr");
    writeExr(good, 8, 6, pixels);
    std::ifstream in(good, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 100u);
    std::mt19937 rng(99);
    int refused = 0, read = 0;
    const int mutants = 600;
    for (int i = 0; i < mutants; ++i) {
        std::string m = bytes;
        if (i < int(bytes.size()) && i % 2 == 0) {
            m.resize(size_t(i / 2) % bytes.size());  // every truncation length over the header and more
        } else {
            for (int k = 0, n = 1 + int(rng() % 8); k < n; ++k) m[rng() % m.size()] = char(rng());
        }
        const std::string path = dir.file("mutant.exr");
        writeFile(path, m);
        SCOPED_TRACE("mutant " + std::to_string(i));
        try {
            const ImageF img = readExrChecked(path, "A");
            ++read;
            EXPECT_EQ(img.rgba.size(), size_t(img.width) * img.height * 4);
        } catch (const std::exception& e) {
            ++refused;
            const std::string msg = e.what();
            EXPECT_FALSE(msg.empty());
            EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        }
    }
    EXPECT_GT(refused, mutants / 4);
    std::printf("exr mutants: %d read, %d refused\n", read, refused);
}

// An opaque filter plus deep shadow maps is one valid setting; two opaque filters are the error.
TEST(OptionRules, OpaqueFilterWithDsmIsValidTwoFiltersAreNot) {
    TempDir dir;
    Cli cli("penumbra test");
    const std::string out = dir.file("x.png");
    std::vector<const char*> argv{"penumbra", "render", "cornell", "-o", out.c_str(), "--shadow", "pcf,dsm", "--dry-run"};
    ASSERT_NO_THROW(cli.app.parse(int(argv.size()), argv.data()));
    EXPECT_EQ(cli.run(), 0);
    EXPECT_EQ(cli.renderSettings.shadow.filter, ShadowFilter::Pcf);
    EXPECT_TRUE(cli.renderSettings.dsm.enabled);

    std::string message;
    EXPECT_EQ(runCli({"render", "cornell", "-o", out, "--shadow", "pcf,vsm"}, message), Result::ParseError);
    EXPECT_NE(message.find("one filter for opaque casters"), std::string::npos) << message;
}
