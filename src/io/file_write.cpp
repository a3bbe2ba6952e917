#include "io/file_write.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace penumbra {
namespace {

[[noreturn]] void fail(const std::string& path, const char* step, int error) {
    throw std::runtime_error("cannot write " + path + ": " + step + " failed (" + std::strerror(error) + ")");
}

}  // namespace

void writeFileChecked(const std::string& path, std::string_view bytes) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) fail(path, "open", errno);
    const size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), file);
    int error = written == bytes.size() ? 0 : (errno ? errno : EIO);
    const char* step = "write";
    if (!error && std::fflush(file) != 0) error = errno, step = "flush";
    // fclose reports what the last buffered write could not do; it releases the stream either way.
    if (std::fclose(file) != 0 && !error) error = errno, step = "close";
    if (error) fail(path, step, error);
}

void writeTextFile(const std::string& path, const std::string& text) { writeFileChecked(path, text + "\n"); }

}  // namespace penumbra
