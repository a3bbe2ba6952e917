// `render --sequence N`: N frames at --fps from --time, numbered image files (a printf %d field in
// -o) or an mp4 encoded by the `ffmpeg` program.
#pragma once
#include <string>

namespace penumbra {

// The file name of frame `index` for an output pattern with one %d field (%d, %04d...).
std::string sequenceFrameName(const std::string& pattern, int index);
// Throws std::invalid_argument (one line) when `pattern` has no (or more than one) %d field.
void checkSequencePattern(const std::string& pattern);
// The ffmpeg program on PATH ("" when there is none).
std::string findFfmpeg();
// Encodes frames (a pattern of PNG files numbered from 0) to `mp4` at `fps`; throws on failure.
void encodeMp4(const std::string& ffmpeg, const std::string& framePattern, double fps, const std::string& mp4);

}  // namespace penumbra
