// Built-in scenes of the GI evaluation suite (`penumbra eval --suite`): an open sunlit street and a
// closed room under a point light: the open and the closed case beside cornell (docs/evaluation.md).
#pragma once
#include "scene/scene.h"

namespace penumbra {

// A 10 m wide, 40 m long street between coloured facades (6-10 m high) under a low sun (20 degrees
// above the horizon, across and along the street): long shadows, one sunlit side, bounce across.
Scene makeStreet();

// A closed 6 x 3 x 5 m room with coloured walls and three pieces of furniture, lit by one point
// light under the ceiling: every bounce stays inside.
Scene makeRoom();

}  // namespace penumbra
