#include "app/sequence.h"

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

namespace penumbra {
namespace {

const std::regex kField("%(0?[0-9]*)d");

}  // namespace

void checkSequencePattern(const std::string& pattern) {
    const auto begin = std::sregex_iterator(pattern.begin(), pattern.end(), kField);
    const ptrdiff_t fields = std::distance(begin, std::sregex_iterator());
    const std::string rest = std::regex_replace(pattern, kField, "");
    if (fields != 1 || rest.find('%') != std::string::npos)
        throw std::invalid_argument(fmt::format(
            "-o {}: a sequence needs one %d field for the frame number (e.g. out_%04d.png), or an .mp4 output", pattern));
}

std::string sequenceFrameName(const std::string& pattern, int index) {
    std::smatch m;
    if (!std::regex_search(pattern, m, kField)) return pattern;
    const std::string spec = m[1].str();
    const int width = spec.empty() ? 0 : std::atoi(spec.c_str());
    const std::string number = fmt::format("{:0{}d}", index, width);
    return m.prefix().str() + number + m.suffix().str();
}

std::string findFfmpeg() {
    const char* path = std::getenv("PATH");
    if (!path) return "";
    std::string dirs(path);
    size_t start = 0;
    while (start <= dirs.size()) {
        const size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string candidate = (end > start ? dirs.substr(start, end - start) : ".") + "/ffmpeg";
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return "";
}

void encodeMp4(const std::string& ffmpeg, const std::string& framePattern, double fps, const std::string& mp4) {
    const std::string rate = fmt::format("{}", fps);
    // yuv420p and even sizes: what players accept; no shell, arguments passed as they are.
    const char* argv[] = {ffmpeg.c_str(), "-y", "-loglevel", "error", "-framerate", rate.c_str(), "-i",
                          framePattern.c_str(), "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
                          "-pix_fmt", "yuv420p", mp4.c_str(), nullptr};
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot start ffmpeg (fork failed)");
    if (pid == 0) {
        execv(ffmpeg.c_str(), const_cast<char* const*>(argv));
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(fmt::format("ffmpeg failed to encode {} (exit status {})", mp4,
                                             WIFEXITED(status) ? WEXITSTATUS(status) : -1));
}

}  // namespace penumbra
