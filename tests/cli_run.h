// The penumbra executable (PENUMBRA_BIN) run as a child process from a test, in a scratch folder that
// goes away with the test. (cli_test.cpp has its own runner with environment control.)
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace penumbra::test {

struct ScratchDir {
    std::filesystem::path path;
    explicit ScratchDir(const std::string& name = "test")
        : path(std::filesystem::temp_directory_path() / fmt::format("penumbra_{}_{}", name, getpid())) {
        std::filesystem::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

inline std::string readText(const std::string& path) {
    std::ifstream f(path);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

struct Cli {
    int status;
    std::string out, err;
};

// Runs the penumbra executable with `args` (on lavapipe: the test environment pins the ICD), at most 60 s.
inline Cli runCli(const ScratchDir& dir, const std::string& args) {
    const std::string out = dir.file("out.txt"), err = dir.file("err.txt");
    const int rc = std::system(fmt::format("timeout 60 {} {} >{} 2>{}", PENUMBRA_BIN, args, out, err).c_str());
    return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, readText(out), readText(err)};
}

// What bad input gets (CONTRIBUTING.md): a non-zero exit and one line "penumbra: error: ...", which names
// `mentions`. `context` says which input it was.
inline void expectOneErrorLine(const Cli& r, const std::string& context, const std::string& mentions = "") {
    EXPECT_NE(r.status, 0) << context;
    EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << context << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << context << "\n" << r.err;
    EXPECT_NE(r.err.find(mentions), std::string::npos) << context << ": expected '" << mentions << "' in: " << r.err;
}

// Runs `args` and expects them refused so.
inline void expectRefused(const ScratchDir& dir, const std::string& args, const std::string& mentions = "") {
    expectOneErrorLine(runCli(dir, args), args, mentions);
}

}  // namespace penumbra::test
