#include "app/option_checks.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// The value as a double, or an error text: the whole string must be one number.
std::string parseNumber(const std::string& text, double& value) {
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a number";
    if (!std::isfinite(value) || errno == ERANGE) return "'" + text + "' is not a finite number";
    return "";
}

std::string shortNumber(double v) { return fmt::format("{:g}", v); }

// Whether a file can be created in `dir`: tried with a probe file (permission bits say nothing for
// root, or on read-only and pseudo file systems such as /proc).
bool writableDirectory(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return false;
    std::string probe = (dir / ".penumbra-write-test-XXXXXX").string();
    const int fd = mkstemp(probe.data());
    if (fd < 0) return false;
    close(fd);
    unlink(probe.c_str());
    return true;
}

// The nearest ancestor of `path` that exists (the current directory for a relative path's root).
fs::path nearestExisting(fs::path path) {
    std::error_code ec;
    path = fs::absolute(path, ec);
    while (!path.empty() && !fs::exists(path, ec) && path.has_parent_path() && path.parent_path() != path)
        path = path.parent_path();
    return path;
}

}  // namespace

CLI::Validator finiteRange(double min, double max) {
    const std::string range = "[" + shortNumber(min) + ", " + shortNumber(max) + "]";
    return CLI::Validator(
        [min, max, range](std::string& text) -> std::string {
            double v = 0.0;
            const std::string err = parseNumber(text, v);
            if (!err.empty()) return err;
            if (v < min || v > max) return text + " is not in " + range;
            return "";
        },
        "in " + range, "FINITE_RANGE");
}

void requireFiniteNumbers(CLI::App& app) {
    const CLI::Validator finite(
        [](std::string& text) -> std::string {
            double v = 0.0;
            return parseNumber(text, v);
        },
        "", "FINITE");
    for (CLI::Option* opt : app.get_options()) {
        const std::string type = opt->get_type_name();
        if (type.rfind("FLOAT", 0) == 0 || type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0) opt->check(finite);
    }
    for (CLI::App* sub : app.get_subcommands({})) requireFiniteNumbers(*sub);
}

void checkWritable(const std::string& path, const std::string& option, bool directory) {
    std::error_code ec;
    const fs::path p(path);
    if (directory) {
        if (fs::exists(p, ec) && !fs::is_directory(p, ec))
            throw std::invalid_argument(fmt::format("{} {}: exists and is not a directory", option, path));
        const fs::path base = nearestExisting(p);
        if (!writableDirectory(base))
            throw std::invalid_argument(fmt::format("{} {}: cannot create or write there ({} is not a writable "
                                                    "directory)", option, path, base.string()));
        return;
    }
    if (path.empty() || path.back() == '/' || fs::is_directory(p, ec))
        throw std::invalid_argument(fmt::format("{} {}: is a directory, not a file", option, path));
    if (fs::exists(p, ec)) {
        if (!std::ofstream(p, std::ios::app))  // opened for appending: the file is left as it is
            throw std::invalid_argument(fmt::format("{} {}: the file is not writable", option, path));
        return;
    }
    const fs::path parent = fs::absolute(p, ec).parent_path();
    if (!writableDirectory(parent))
        throw std::invalid_argument(fmt::format("{} {}: cannot write there ({} is not a writable directory)", option,
                                                path, parent.string()));
}

}  // namespace penumbra
