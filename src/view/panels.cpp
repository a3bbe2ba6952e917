#include "view/panels.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/names.h"
#include "dsm/dsm_options.h"
#include "lpv/lpv_options.h"
#include "renderer/render_options.h"
#include "rsm/rsm_options.h"
#include "shadow/shadow_options.h"

namespace penumbra::view {
namespace {

constexpr size_t kFrameHistory = 240;

// The windows' default share of the display (width, height): together under a quarter of it, so
// that the image stays visible; they follow the display when its size changes.
constexpr float kMargin = 8.0f;
constexpr float kSceneShare[2] = {0.24f, 0.48f};
constexpr float kTimingsShare[2] = {0.25f, 0.26f};
constexpr float kProbeShare[2] = {0.25f, 0.20f};


// A sun's direction of travel from the azimuth and elevation of the direction towards it.
glm::vec3 sunDirection(float azimuthDeg, float elevationDeg) {
    const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

void azimuthElevation(const glm::vec3& direction, float& azimuthDeg, float& elevationDeg) {
    const glm::vec3 toSun = -glm::normalize(direction);
    azimuthDeg = glm::degrees(std::atan2(toSun.x, toSun.z));
    elevationDeg = glm::degrees(std::asin(std::clamp(toSun.y, -1.0f, 1.0f)));
}

const char* typeName(LightType t) {
    switch (t) {
        case LightType::Directional: return "directional";
        case LightType::Spot: return "spot";
        case LightType::Point: return "point";
    }
    return "?";
}

// The editors of one light; true when it changed.
bool lightEditor(Light& l) {
    bool changed = false;
    if (l.type == LightType::Directional || l.type == LightType::Spot) {
        float az, el;
        azimuthElevation(l.direction, az, el);
        const bool a = ImGui::SliderFloat("azimuth", &az, -180.0f, 180.0f, "%.1f deg");
        const bool e = ImGui::SliderFloat("elevation", &el, -89.9f, 89.9f, "%.1f deg");
        if (a || e) l.direction = sunDirection(az, el), changed = true;
    }
    if (l.type != LightType::Directional) changed |= ImGui::DragFloat3("position", &l.position.x, 0.01f);
    changed |= ImGui::DragFloat(l.type == LightType::Directional ? "irradiance E" : "intensity I", &l.intensity, 0.01f,
                                0.0f, 1e6f);
    changed |= ImGui::ColorEdit3("colour", &l.color.x);
    if (l.type == LightType::Spot) {
        float outer = glm::degrees(l.outerConeAngle);
        if (ImGui::SliderFloat("outer cone", &outer, 1.0f, 89.0f, "%.1f deg"))
            l.outerConeAngle = glm::radians(outer), l.innerConeAngle = std::min(l.innerConeAngle, l.outerConeAngle),
            changed = true;
    }
    changed |= ImGui::Checkbox("casts shadow", &l.castsShadow);
    return changed;
}

// One word per name in PanelsState::text(): "GPU time" -> "GPU-time".
std::string nameWithoutSpaces(std::string name) {
    std::replace(name.begin(), name.end(), ' ', '-');
    return name;
}

}  // namespace

void Panels::recordFrameTime(double ms) {
    frameMs_.push_back(float(ms));
    while (frameMs_.size() > kFrameHistory) frameMs_.pop_front();
}

void Panels::loadScene(ViewSession& session, const std::string& path) {
    try {
        session.loadScene(path);
        error_.clear();
    } catch (const std::exception& e) {
        error_ = fmt::format("{}: {}", path, e.what());
    }
}

void Panels::apply(ViewSession& session, const std::string& option, const std::string& value) {
    try {
        session.set(option, value);
        error_.clear();
        edits_.erase(option);
    } catch (const std::exception& e) {
        error_ = e.what();
    }
}

void Panels::animate(ViewSession& session, double dt) {
    if (!turnSun_) return;
    std::vector<Light> lights = session.lights();
    for (Light& l : lights)
        if (l.type == LightType::Directional) {
            float az, el;
            azimuthElevation(l.direction, az, el);
            l.direction = sunDirection(std::fmod(az + sunDegreesPerSecond_ * float(dt) + 540.0f, 360.0f) - 180.0f, el);
        }
    session.setLights(std::move(lights));
}

void Panels::dragSun(ViewSession& session, float dx, float dy) {
    std::vector<Light> lights = session.lights();
    for (Light& l : lights)
        if (l.type == LightType::Directional) {
            float az, el;
            azimuthElevation(l.direction, az, el);
            l.direction = sunDirection(az + 0.25f * dx, std::clamp(el - 0.25f * dy, -89.9f, 89.9f));
            session.setLights(std::move(lights));
            return;
        }
}

// The right half of the image from a second renderer with one option changed, e.g. "gi lpv".
void Panels::splitSection(ViewSession& session) {
    ImGui::InputText("B: OPTION VALUE", &splitEdit_);
    if (ImGui::Button(session.rendererB() ? "update B" : "split")) {
        const size_t space = splitEdit_.find(' ');
        try {
            if (space == std::string::npos) throw std::invalid_argument("expected OPTION VALUE, e.g. shadow pcss");
            session.setSplit(splitEdit_.substr(0, space), splitEdit_.substr(space + 1));
            error_.clear();
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("off")) session.clearSplit();
}

// The split line and which side is which, over the image.
void Panels::splitLabels(ViewSession& session) {
    if (!session.rendererB()) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddLine({size.x * 0.5f, 0.0f}, {size.x * 0.5f, size.y}, IM_COL32(255, 255, 255, 200), 1.0f);
    draw->AddText({size.x * 0.5f - 16.0f, size.y - 20.0f}, IM_COL32(255, 255, 255, 255), "A");
    draw->AddText({size.x * 0.5f + 8.0f, size.y - 20.0f}, IM_COL32(255, 255, 255, 255), session.splitLabel().c_str());
}

float PanelsState::coverage() const {
    float area = 0.0f;
    for (const Rect& r : windows) {
        const float w = std::min(r.x + r.width, displayWidth) - std::max(r.x, 0.0f);
        const float h = std::min(r.y + r.height, displayHeight) - std::max(r.y, 0.0f);
        area += std::max(w, 0.0f) * std::max(h, 0.0f);
    }
    return displayWidth > 0 && displayHeight > 0 ? area / (displayWidth * displayHeight) : 0.0f;
}

std::string PanelsState::text() const {
    std::string out = fmt::format("display {} {}\ncoverage {:.4f}\n", displayWidth, displayHeight, coverage());
    for (const Rect& r : windows)
        out += fmt::format("window {} {} {} {} {}\n", nameWithoutSpaces(r.window), r.x, r.y, r.width, r.height);
    for (const std::string& p : passes) out += fmt::format("pass {}\n", p);
    for (const auto& [name, value] : options) out += fmt::format("option {} {}\n", name, value);
    for (const auto& [name, v] : probe) out += fmt::format("probe {} {} {} {}\n", name, v.x, v.y, v.z);
    return out;
}

void Panels::draw(ViewSession& session, CameraControl& control, const vk::Swapchain& swapchain) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    relayout_ |= display.x != state_.displayWidth || display.y != state_.displayHeight;
    state_ = {display.x, display.y, {}, {}, {}, {}};
    splitLabels(session);
    if (!session.showPanels) return;
    session.catchUpPanels();
    sceneWindow(session, control);
    timingsWindow(session, swapchain);
    probeWindow(session);
    relayout_ = false;
}

// A window's place as a share of the display: set when the display size changed, free otherwise.
void Panels::placeWindow(const char* name, float x, float y, float width, float height) {
    const ImGuiCond when = relayout_ ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos({x, y}, when);
    ImGui::SetNextWindowSize({width, height}, when);
    ImGui::Begin(name);
}

// Between Begin and End: the window's rectangle as drawn.
void Panels::recordWindow(const char* name) {
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    state_.windows.push_back({name, pos.x, pos.y, size.x, size.y});
}

void Panels::sceneWindow(ViewSession& session, CameraControl& control) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    placeWindow("penumbra", kMargin, kMargin, display.x * kSceneShare[0], display.y * kSceneShare[1]);
    recordWindow("penumbra");
    ImGui::TextDisabled("F1 hides the panels");
    const Scene& scene = session.scene();
    ImGui::Text("%s: %zu triangles, %zu strands", scene.name.c_str(), scene.triangleCount(), scene.strands.size());
    ImGui::TextDisabled("drop a .gltf/.glb onto the window to load it");
    if (!error_.empty()) ImGui::TextColored({1.0f, 0.4f, 0.3f, 1.0f}, "%s", error_.c_str());
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        int mode = int(control.mode);
        ImGui::RadioButton("fly (WASD QE, right-drag)", &mode, 0);
        ImGui::SameLine();
        ImGui::RadioButton("orbit (left-drag)", &mode, 1);
        control.mode = CameraControl::Mode(mode);
        ImGui::SliderFloat("speed", &control.speed, 1e-3f, 100.0f, "%.3g /s", ImGuiSliderFlags_Logarithmic);
        for (size_t i = 0; i < scene.cameras.size(); ++i)
            if (ImGui::Button(fmt::format("file camera {}", i).c_str())) session.setCamera(scene.cameras[i]);
        const Camera& c = session.camera();
        ImGui::TextDisabled("eye %.3g %.3g %.3g  target %.3g %.3g %.3g", c.eye.x, c.eye.y, c.eye.z, c.target.x,
                            c.target.y, c.target.z);
    }
    if (session.moves() && ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) timeSection(session);
    if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) lightsSection(session);
    if (ImGui::CollapsingHeader("A/B split view")) splitSection(session);
    if (ImGui::CollapsingHeader("Overlays")) {
        ImGui::Checkbox("shadow frusta (cascade bounds, spot cones, cube faces)", &overlays_.shadowFrusta);
        ImGui::Checkbox("LPV cascade boxes", &overlays_.lpvBoxes);
    }
    optionsSection(session);
    ImGui::End();
}

// Animation and motion paths: play/pause and a time slider (the slider's range grows with the time).
void Panels::timeSection(ViewSession& session) {
    if (ImGui::Button(session.playing ? "pause" : "play")) session.playing = !session.playing;
    ImGui::SameLine();
    if (ImGui::Button("|<")) session.time = 0.0f;
    ImGui::SameLine();
    const float range = std::max(10.0f, std::ceil(session.time / 10.0f) * 10.0f);
    ImGui::SliderFloat("t (s)", &session.time, 0.0f, range, "%.2f");
}

void Panels::lightsSection(ViewSession& session) {
    std::vector<Light> lights = session.lights();
    bool changed = false;
    int remove = -1;
    for (size_t i = 0; i < lights.size(); ++i) {
        ImGui::PushID(int(i));
        if (ImGui::TreeNode("light", "%zu: %s %s", i, typeName(lights[i].type), lights[i].name.c_str())) {
            changed |= lightEditor(lights[i]);
            if (ImGui::Button("remove")) remove = int(i);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (remove >= 0) lights.erase(lights.begin() + remove), changed = true;
    const Bounds& b = session.scene().bounds;
    Light added;
    added.position = b.empty() ? glm::vec3(0.0f) : b.center() + glm::vec3(0.0f, 0.4f * (b.max.y - b.min.y), 0.0f);
    added.intensity = b.empty() ? 1.0f : b.radius() * b.radius();  // about E = 1 a radius away
    for (LightType t : {LightType::Directional, LightType::Spot, LightType::Point}) {
        if (t != LightType::Directional) ImGui::SameLine();
        if (ImGui::Button(fmt::format("add {}", typeName(t)).c_str())) {
            added.type = t;
            if (t == LightType::Directional) added.intensity = 3.0f, added.direction = sunDirection(30.0f, 45.0f);
            lights.push_back(added);
            changed = true;
        }
    }
    ImGui::Checkbox("turn the sun", &turnSun_);
    ImGui::SameLine();
    ImGui::SliderFloat("deg/s", &sunDegreesPerSecond_, -90.0f, 90.0f, "%.0f");
    ImGui::TextDisabled("ctrl + left-drag turns the first directional light");
    if (changed) session.setLights(std::move(lights));
}

// Sliders for the debug views that show one slice or layer: the LPV/GV slice and the light-space layer.
void Panels::debugViewSliders(ViewSession& session) {
    const RenderSettings& rs = session.settings();
    if (rs.aov == Aov::LpvSlice || rs.aov == Aov::GvSlice) {
        int slice = int(rs.lpv.sliceIndex);
        if (ImGui::SliderInt("lpv-slice", &slice, 0, int(rs.lpv.resolution) - 1))
            apply(session, "lpv-slice", std::to_string(slice));
    } else if (rs.aov == Aov::RsmDepth || rs.aov == Aov::RsmNormal || rs.aov == Aov::RsmFlux ||
               rs.aov == Aov::ShadowMap) {
        int layer = int(rs.aovLayer);
        const ShadowLayers* layers = session.renderer().blackboard().get(names::kShadowLayers);
        const int last = std::max(int(layers ? layers->layers.size() : 0) - 1, 0);  // views clamp to theirs
        if (ImGui::SliderInt("aov-layer", &layer, 0, last)) apply(session, "aov-layer", std::to_string(layer));
    }
}

// Every option of `render` under its CLI name, grouped per technique: choices as combo boxes,
// flags as check boxes, the rest as text fields applied on Enter through the CLI's own parser.
void Panels::optionsSection(ViewSession& session) {
    debugViewSliders(session);
    const std::vector<OptionInfo> options = session.options();
    std::vector<std::string> groups;
    for (const OptionInfo& o : options)
        if (std::find(groups.begin(), groups.end(), o.group) == groups.end()) groups.push_back(o.group);
    const RenderSettings& rs = session.settings();
    for (const OptionInfo& o : options) state_.options.emplace_back(o.name, o.value);
    for (const std::string& group : groups) {
        // The groups of the techniques in use start open.
        const bool inUse = group == shadowOptions().title || group == frameOptionTable().title ||
                           (group == rsmOptions().title && rs.gi == GiMode::Rsm) ||
                           (group == lpvOptions().title && rs.gi == GiMode::Lpv) ||
                           (group == dsmOptions().title && rs.dsm.enabled);
        ImGui::SetNextItemOpen(inUse, ImGuiCond_Once);
        if (!ImGui::CollapsingHeader(group.c_str())) continue;
        for (const OptionInfo& o : options) {
            if (o.group != group) continue;
            ImGui::PushID(o.name.c_str());
            if (o.flag) {
                bool on = o.value == "on" || o.value == "true";
                if (ImGui::Checkbox(o.name.c_str(), &on)) apply(session, o.name, on ? "on" : "off");
            } else if (!o.choices.empty()) {
                if (ImGui::BeginCombo(o.name.c_str(), o.value.empty() ? "(default)" : o.value.c_str())) {
                    for (const std::string& c : o.choices)
                        if (ImGui::Selectable(c.c_str(), c == o.value)) apply(session, o.name, c);
                    ImGui::EndCombo();
                }
            } else {
                auto it = edits_.try_emplace(o.name, o.value).first;
                if (ImGui::InputTextWithHint(o.name.c_str(), "(default)", &it->second,
                                             ImGuiInputTextFlags_EnterReturnsTrue))
                    apply(session, o.name, it->second);
                if (!ImGui::IsItemActive() && !ImGui::IsItemDeactivated()) it->second = o.value;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("--%s: %s", o.name.c_str(), o.help.c_str());
            ImGui::PopID();
        }
    }
}

void Panels::timingsWindow(ViewSession& session, const vk::Swapchain& swapchain) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = display.x * kTimingsShare[0];
    placeWindow("GPU time", display.x - width - kMargin, kMargin, width, display.y * kTimingsShare[1]);
    recordWindow("GPU time");
    const RenderSettings& s = session.settings();
    ImGui::Text("%ux%u, %s present", s.width, s.height, vk::presentModeName(swapchain.presentMode()));
    if (!frameMs_.empty()) {
        std::vector<float> ms(frameMs_.begin(), frameMs_.end());
        const float newest = ms.back();
        const float top = *std::max_element(ms.begin(), ms.end());
        ImGui::PlotLines("##frame", ms.data(), int(ms.size()), 0, fmt::format("frame {:.2f} ms", newest).c_str(), 0.0f,
                         top * 1.1f, {0, 40});
    }
    // Per-pass scopes make the passes run one after another (Renderer::setPassScopes): off shows the
    // frame as it runs, independent passes together.
    ImGui::Checkbox("time every pass (in order)", &passScopes_);
    session.renderer().setPassScopes(passScopes_);
    // After a settings change the newest completed frame may still be one of the old settings: its
    // passes are not those of the image on screen.
    if (passScopes_ && !session.frameMatchesSettings()) ImGui::TextDisabled("(waiting for the frame)");
    else if (passScopes_ && ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableHeadersRow();
        double total = 0.0;
        for (const vk::ScopeTiming& t : session.renderer().timings()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(t.name.c_str());
            state_.passes.push_back(t.name);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", t.ms);
            total += t.ms;
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("sum of passes");
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", total);
        ImGui::EndTable();
    }
    ImGui::End();
}

// Every AOV at the probed pixel, as the newest completed frame computed it (the B renderer's on the
// right half of a split view).
void Panels::probeWindow(ViewSession& session) {
    if (!session.probePixel) return;
    const glm::uvec2 pixel = *session.probePixel;
    Renderer* source = session.rendererB() && pixel.x >= session.settings().width / 2 ? session.rendererB()
                                                                                     : &session.renderer();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = display.x * kProbeShare[0], height = display.y * kProbeShare[1];
    placeWindow("Pixel probe", display.x - width - kMargin, display.y - height - kMargin, width, height);
    recordWindow("Pixel probe");
    ImGui::Text("pixel %u, %u%s", pixel.x, pixel.y, source == &session.renderer() ? "" : " (B)");
    const std::optional<gpu::PixelProbe>& p = source->probe();
    if (!p || !session.frameMatchesSettings()) ImGui::TextDisabled("(waiting for the frame)");
    else if (p->surface == 0) ImGui::Text("background (depth %.3f: the far plane)", p->eyeDistance);
    else {
        const auto row = [this](const char* name, glm::vec3 v) {
            ImGui::Text("%-10s %8.4f %8.4f %8.4f", name, v.x, v.y, v.z);
            state_.probe.emplace_back(name, v);
        };
        row("final", p->finalRadiance);
        row("direct", p->direct);
        row("indirect", p->indirect);
        row("irradiance", p->irradiance);
        row("albedo", p->albedo);
        row("normal", p->normal);
        row("position", p->position);
        ImGui::Text("%-10s %9.4f", "depth", p->eyeDistance);
        ImGui::Text("%-10s %9.4f (layer %.2f)", "shadow", p->shadowVisibility, p->shadowLayer);
        ImGui::Text("%-10s %9.4f", "dsm", p->transmittance);
        ImGui::Text("%-10s %9.3f %9.3f px", "velocity", p->velocity.x, p->velocity.y);
    }
    ImGui::End();
}

}  // namespace penumbra::view
