#include "app/frame_cli.h"

#include "app/option_cli.h"

namespace penumbra {

void addFrameOptions(CLI::App& cmd, FrameOptions& o, RenderSettings& rs) {
    setFrameDefaults(rs);
    cmd.add_option("scene", o.scene, sceneArgumentHelp());
    addOptionRows(cmd, frameInputOptions(), &o);
    addRenderOptionRows(cmd, rs);
    addMotionOptions(cmd, o);
}

void addMotionOptions(CLI::App& cmd, FrameOptions& o) { addOptionRows(cmd, motionOptions(), &o); }

}  // namespace penumbra
