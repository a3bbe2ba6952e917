#include "frame/input_parse.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "scene/light_limits.h"

namespace penumbra {
namespace {

std::vector<float> numbers(const std::string& text) {
    std::vector<float> out;
    std::stringstream ss(text);
    for (std::string item; std::getline(ss, item, ',');) {
        size_t used = 0;
        float v = 0.0f;
        try {
            v = std::stof(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != item.size() || item.empty() || !std::isfinite(v))
            throw std::invalid_argument(fmt::format("'{}' is not a number", item));
        // Larger magnitudes overflow lengths and matrices in single precision (NaN images).
        if (std::abs(v) > 1e9f) throw std::invalid_argument(fmt::format("{} is out of range (|x| <= 1e9)", item));
        out.push_back(v);
    }
    return out;
}

float radians(float degrees) { return degrees * 3.14159265358979f / 180.0f; }

glm::vec3 unit(const glm::vec3& v, const std::string& what) {
    if (glm::length(v) < 1e-6f) throw std::invalid_argument(what + " must not be zero");
    return glm::normalize(v);
}

// Intensity x colour above kMaxLightStrength overflows the RGBA16F lighting targets to infinity (a
// black image). The suggestion, rounded down to 4 significant digits, lies inside the bound.
void checkLightStrength(const Light& l) {
    const float brightest = std::max({l.color.x, l.color.y, l.color.z});
    if (double(l.intensity) * brightest <= kMaxLightStrength) return;
    const double largest = double(kMaxLightStrength) / brightest;
    const double step = std::pow(10.0, std::floor(std::log10(largest)) - 3.0);
    throw std::invalid_argument(fmt::format(
        "intensity {:g} x colour {:g} = {:g} exceeds {:g}, the largest value of the RGBA16F lighting targets; "
        "the largest intensity with this colour is {:g}", l.intensity, brightest, double(l.intensity) * brightest,
        kMaxLightStrength, std::floor(largest / step) * step));
}

}  // namespace

Camera parseCamera(const std::string& value) {
    std::vector<float> v = numbers(value);
    if (v.size() != 10)
        throw std::invalid_argument("expected 10 numbers: eye x,y,z, target x,y,z, up x,y,z, fovy degrees");
    Camera c;
    c.eye = {v[0], v[1], v[2]};
    c.target = {v[3], v[4], v[5]};
    c.up = unit({v[6], v[7], v[8]}, "the up vector");
    if (glm::length(c.target - c.eye) < 1e-6f) throw std::invalid_argument("eye and target coincide");
    // Looking along the up vector leaves the image's roll undefined (lookAt degenerates: a black image).
    if (glm::length(glm::cross(glm::normalize(c.target - c.eye), c.up)) < 1e-3f)
        throw std::invalid_argument("the view direction (target - eye) is parallel to the up vector");
    if (v[9] <= 0.0f || v[9] >= 180.0f) throw std::invalid_argument("fovy must be in (0, 180) degrees");
    c.fovy = radians(v[9]);
    return c;
}

Light parseLight(const std::string& value) {
    const size_t comma = value.find(',');
    const std::string type = value.substr(0, comma);
    std::vector<float> v = comma == std::string::npos ? std::vector<float>{} : numbers(value.substr(comma + 1));
    Light l;
    l.name = "given " + type + " light";
    if (type == "directional" && (v.size() == 4 || v.size() == 7)) {
        l.type = LightType::Directional;
        l.direction = unit({v[0], v[1], v[2]}, "the direction");
        l.intensity = v[3];
        if (v.size() == 7) l.color = {v[4], v[5], v[6]};
        if (glm::any(glm::lessThan(l.color, glm::vec3(0.0f))))
            throw std::invalid_argument("colour components must not be negative");
    } else if (type == "spot" && (v.size() == 8 || v.size() == 9)) {
        l.type = LightType::Spot;
        l.position = {v[0], v[1], v[2]};
        l.direction = unit({v[3], v[4], v[5]}, "the direction");
        l.intensity = v[6];
        l.outerConeAngle = radians(v[7]);
        l.innerConeAngle = v.size() == 9 ? radians(v[8]) : 0.0f;
        if (v[7] <= 0.0f || v[7] >= 90.0f) throw std::invalid_argument("spot: outer angle must be in (0, 90)");
        if (v.size() == 9 && (v[8] < 0.0f || v[8] >= v[7]))
            throw std::invalid_argument("spot: inner angle must be in [0, outer angle)");
    } else if (type == "point" && v.size() == 4) {
        l.type = LightType::Point;
        l.position = {v[0], v[1], v[2]};
        l.intensity = v[3];
    } else {
        throw std::invalid_argument(
            "expected directional,dx,dy,dz,I[,r,g,b] | spot,px,py,pz,dx,dy,dz,I,outer_deg[,inner_deg] | "
            "point,px,py,pz,I");
    }
    if (l.intensity < 0.0f) throw std::invalid_argument("intensity must not be negative");
    checkLightStrength(l);
    return l;
}

// In AOV_* order (shaders/shared/types.h).
std::vector<std::string> aovNames() {
    return {"direct",   "albedo",    "normal",   "depth",   "shadow",        "final",
            "indirect", "lpv-slice", "gv-slice", "cascade", "transmittance", "dsm-lists",
            "rsm-depth", "rsm-normal", "rsm-flux", "shadow-map", "velocity", "sky"};
}

Aov parseAov(const std::string& value) {
    const std::vector<std::string> names = aovNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == value) return static_cast<Aov>(i);
    throw std::invalid_argument(fmt::format("unknown AOV '{}' (one of: {})", value, fmt::join(names, ", ")));
}

}  // namespace penumbra
