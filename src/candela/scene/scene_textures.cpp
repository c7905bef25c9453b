// Material parameters that may be textures.
#include "candela/scene/scene_sections.h"

namespace candela {

ColorParam read_color_param(const JsonCursor& c, Scene&, const Bounds& bounds) {
    return ColorParam{c.colour(bounds)};
}

FloatParam read_float_param(const JsonCursor& c, Scene&, const Bounds& bounds) {
    return FloatParam{c.number_f(bounds)};
}

}  // namespace candela
