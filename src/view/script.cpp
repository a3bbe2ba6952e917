#include "view/script.h"

#include <charconv>
#include <cmath>
#include <type_traits>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "frame/input_parse.h"
#include "io/image_io.h"

namespace penumbra::view {
namespace {

std::vector<std::string> split(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// As `render --frames` and `--time` take them: a script cannot ask for more work than the CLI can.
constexpr int kMaxScriptFrames = 100000;
constexpr float kMaxScriptTime = 1e6f;

// The whole word as a number, or an error naming what was expected; a floating-point number must be
// finite (from_chars reads "nan" and "inf").
template <class T> T number(const std::string& word, const char* what) {
    T value{};
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    bool finite = true;
    if constexpr (std::is_floating_point_v<T>) finite = std::isfinite(value);
    if (ec != std::errc() || end != word.data() + word.size() || !finite)
        throw std::invalid_argument(fmt::format("{}: expected {}, got '{}'", what, what, word));
    return value;
}

// `number` within [lo, hi], or an error naming the range.
template <class T> T numberIn(const std::string& word, const char* what, T lo, T hi) {
    const T value = number<T>(word, what);
    if (value < lo || value > hi)
        throw std::invalid_argument(fmt::format("{} {} is out of range [{}, {}]", what, word, lo, hi));
    return value;
}

void expectWords(const std::vector<std::string>& words, size_t n, const char* usage) {
    if (words.size() != n) throw std::invalid_argument(fmt::format("expected: {}", usage));
}

std::string screenshotPath(const std::vector<std::string>& words, bool png_only) {
    expectWords(words, 1, png_only ? "screenshot-ui PATH.png" : "screenshot PATH.png|PATH.exr");
    const std::string ext = fileExtension(words[0]);
    if (ext != ".png" && (png_only || ext != ".exr"))
        throw std::invalid_argument(fmt::format("{}: the path must end in {}", words[0],
                                                png_only ? ".png" : ".png or .exr"));
    return words[0];
}

}  // namespace

Script::Script(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw ScriptError(fmt::format("{}: cannot read the script", path));
}

ScriptStep Script::run(ViewSession& session) {
    for (std::string text; std::getline(in_, text);) {
        ++line_;
        const size_t hash = text.find('#');
        if (hash != std::string::npos) text.resize(hash);
        std::istringstream in(text);
        std::string command;
        if (!(in >> command)) continue;
        std::string args;
        std::getline(in, args);
        try {
            ScriptStep step = execute(command, args, session);
            if (step.kind != ScriptStep::Frames || step.frames > 0) return step;
        } catch (const std::exception& e) {
            throw ScriptError(fmt::format("{}:{}: {}", path_, line_, e.what()));
        }
    }
    return {};
}

ScriptStep Script::execute(const std::string& command, const std::string& args, ViewSession& session) {
    const std::vector<std::string> words = split(args);
    ScriptStep step{ScriptStep::Frames, 0, {}};
    if (command == "set") {
        expectWords(words, 2, "set OPTION VALUE");
        session.set(words[0], words[1]);
    } else if (command == "camera") {
        expectWords(words, 1, "camera ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy");
        session.setCamera(parseCamera(words[0]));
    } else if (command == "light") {
        expectWords(words, 2, "light N SPEC");
        session.setLight(number<size_t>(words[0], "a light index"), parseLight(words[1]));
    } else if (command == "time") {
        expectWords(words, 1, "time T");
        session.time = numberIn<float>(words[0], "a time in seconds", -kMaxScriptTime, kMaxScriptTime);
    } else if (command == "play" || command == "pause") {
        expectWords(words, 0, command.c_str());
        session.playing = command == "play";
    } else if (command == "probe") {
        if (words.size() == 1 && words[0] == "off") {
            session.probePixel.reset();
            session.probePinned = false;
        } else {
            expectWords(words, 2, "probe X Y | probe off");
            session.probePixel = glm::uvec2(number<uint32_t>(words[0], "a pixel column"),
                                            number<uint32_t>(words[1], "a pixel row"));
            session.probePinned = true;
        }
    } else if (command == "panels") {
        if (words.size() != 1 || (words[0] != "on" && words[0] != "off"))
            throw std::invalid_argument("expected: panels on|off");
        session.showPanels = words[0] == "on";
    } else if (command == "panels-state") {
        expectWords(words, 1, "panels-state PATH");
        return {ScriptStep::PanelsState, 0, words[0]};
    } else if (command == "frames") {
        expectWords(words, 1, "frames N");
        step.frames = numberIn<int>(words[0], "a frame count", 0, kMaxScriptFrames);
    } else if (command == "screenshot" || command == "screenshot-ui") {
        const bool ui = command == "screenshot-ui";
        return {ui ? ScriptStep::ScreenshotUi : ScriptStep::Screenshot, 0, screenshotPath(words, ui)};
    } else if (command == "quit") {
        expectWords(words, 0, "quit");
        return {};
    } else {
        throw std::invalid_argument(fmt::format(
            "unknown command '{}' (set, camera, light, time, play, pause, probe, panels, panels-state, frames, screenshot, "
            "screenshot-ui, quit)",
            command));
    }
    return step;
}

}  // namespace penumbra::view
