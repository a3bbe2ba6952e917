// The `--sky` value and the sky a frame's lights make of it.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "core/sky.h"
#include "io/image_io.h"

namespace penumbra {
namespace {

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ',');) parts.push_back(p);
    if (!text.empty() && text.back() == ',') parts.push_back("");
    return parts;
}

float parseNumber(const std::string& text, const char* what) {
    size_t used = 0;
    float v = 0.0f;
    try {
        v = std::stof(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(v))
        throw std::invalid_argument(fmt::format("{} '{}' is not a number", what, text));
    return v;
}

void parseUniform(SkySettings& s, const std::vector<std::string>& parts) {
    if (parts.size() != 4) throw std::invalid_argument("uniform takes three radiances: uniform,r,g,b (e.g. uniform,1,1,1)");
    for (int k = 0; k < 3; ++k) {
        s.uniformRadiance[k] = parseNumber(parts[k + 1], "radiance");
        if (s.uniformRadiance[k] < 0.0f) throw std::invalid_argument("a radiance must be >= 0 (e.g. uniform,1,1,1)");
    }
}

void parseAnalytic(SkySettings& s, const std::vector<std::string>& parts) {
    if (parts.size() > 2) throw std::invalid_argument("analytic takes at most a turbidity: analytic[,turbidity]");
    s.turbidity = parts.size() == 2 ? parseNumber(parts[1], "turbidity") : kDefaultTurbidity;
    if (s.turbidity < kMinTurbidity || s.turbidity > kMaxTurbidity)
        throw std::invalid_argument(fmt::format("turbidity must lie in [{}, {}] (e.g. analytic,{})", kMinTurbidity,
                                                kMaxTurbidity, kDefaultTurbidity));
}

// An OpenEXR file starts with the magic number 76 2f 31 01.
void checkMap(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::invalid_argument(fmt::format("cannot open sky map '{}'", path));
    unsigned char magic[4] = {};
    in.read(reinterpret_cast<char*>(magic), 4);
    if (in.gcount() != 4 || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01)
        throw std::invalid_argument(fmt::format("'{}' is not an OpenEXR file", path));
}

bool endsWithExr(const std::string& text) {
    return text.size() > 4 && (text.substr(text.size() - 4) == ".exr" || text.substr(text.size() - 4) == ".EXR");
}

const Light* firstDirectional(const std::vector<Light>& lights) {
    for (const Light& l : lights)
        if (l.type == LightType::Directional) return &l;
    return nullptr;
}

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace

void parseSky(SkySettings& s, const std::string& text) {
    const std::vector<std::string> parts = splitCommas(text);
    const std::string head = parts.empty() ? "" : parts.front();
    if (head == "none" || head == "auto") {
        if (parts.size() != 1) throw std::invalid_argument(fmt::format("{} takes no values", head));
        s.kind = head == "none" ? SkyKind::None : SkyKind::Auto;
    } else if (head == "uniform") {
        parseUniform(s, parts);
        s.kind = SkyKind::Uniform;
    } else if (head == "analytic") {
        parseAnalytic(s, parts);
        s.kind = SkyKind::Analytic;
    } else if (endsWithExr(text)) {
        checkMap(text);
        s.mapPath = text;
        s.kind = SkyKind::Map;
    } else {
        throw std::invalid_argument("is not none, auto, uniform,r,g,b, analytic[,turbidity] or a FILE.exr");
    }
}

std::string skyText(const SkySettings& s) {
    switch (s.kind) {
        case SkyKind::Auto: return "auto";
        case SkyKind::None: return "none";
        case SkyKind::Uniform:
            return fmt::format("uniform,{},{},{}", s.uniformRadiance.r, s.uniformRadiance.g, s.uniformRadiance.b);
        case SkyKind::Analytic: return fmt::format("analytic,{}", s.turbidity);
        case SkyKind::Map: return s.mapPath;
    }
    return "?";
}

float skySunIlluminance(const SkySettings& settings, const std::vector<Light>& lights) {
    if (settings.sunIlluminance > 0.0f) return settings.sunIlluminance;
    const Light* sun = firstDirectional(lights);
    return sun ? sun->intensity * luminance(sun->color) : 0.0f;
}

// Without the user's scale: makeSky scales every kind's table alike.
static std::optional<AnalyticSkyModel> unscaledAnalyticSky(const SkySettings& settings,
                                                           const std::vector<Light>& lights,
                                                           std::vector<std::string>& warnings) {
    const Light* sun = firstDirectional(lights);
    if (!sun) {
        warnings.push_back("the analytic sky follows the first directional light and the scene has none: no sky");
        return std::nullopt;
    }
    if (sun->direction.y > 0.0f) warnings.push_back("the sun is below the horizon: the analytic sky takes it at the horizon");
    return AnalyticSkyModel::make(settings.turbidity, -sun->direction, skySunIlluminance(settings, lights));
}

std::optional<AnalyticSkyModel> makeAnalyticSky(const SkySettings& settings, const std::vector<Light>& lights,
                                                std::vector<std::string>& warnings) {
    std::optional<AnalyticSkyModel> model = unscaledAnalyticSky(settings, lights, warnings);
    if (model) model->scale *= settings.scale;
    return model;
}

Sky makeSky(const SkySettings& settings, const std::vector<Light>& lights, std::vector<std::string>& warnings) {
    const Light* sun = firstDirectional(lights);
    Sky sky;
    switch (settings.kind) {
        case SkyKind::Uniform: sky = Sky::uniform(settings.uniformRadiance); break;
        case SkyKind::Analytic: {
            const std::optional<AnalyticSkyModel> model = unscaledAnalyticSky(settings, lights, warnings);
            if (!model) return sky;
            sky = Sky::analytic(*model);
            break;
        }
        case SkyKind::Map: {
            const ImageF image = readExr(settings.mapPath);
            SkyTable table{image.width, image.height, std::vector<glm::vec3>(size_t(image.width) * image.height)};
            for (size_t i = 0; i < table.texels.size(); ++i)
                table.texels[i] = glm::max(glm::vec3(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]),
                                           glm::vec3(0.0f));
            sky = Sky::map(std::move(table), settings.rotationDegrees);
            if (sun)
                if (const uint32_t clipped = sky.clipSun())
                    warnings.push_back(fmt::format("sky map '{}': its {} brightest texels are clipped (the directional "
                                                   "light is the sun)", settings.mapPath, clipped));
            break;
        }
        default: return sky;
    }
    sky.scale(settings.scale);
    return sky;
}

}  // namespace penumbra
