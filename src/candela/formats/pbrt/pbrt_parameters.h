#pragma once
// A pbrt-v4 directive's parameter list, as the parser hands it over: `"float radius" [ 3 ]` is a
// parameter of type "float", name "radius", one number. The parser checks the syntax and that
// values fit their type (numbers for numeric types, strings for string/texture/spectrum names,
// bools for bool); what a parameter means is the importer's business (pbrt_importer.h), which
// also reports parameters nobody read.
#include <cstdint>
#include <string>
#include <vector>

#include "candela/formats/pbrt/pbrt_location.h"

namespace candela::pbrt {

struct Parameter {
    std::string type;  // as written: integer, float, point2, vector2, point3, vector3, normal,
                       // normal3, point, vector, color, rgb, spectrum, blackbody, bool, string,
                       // texture
    std::string name;
    Location location;  // of the parameter's "type name" string
    // Exactly one of these holds the values, by type: numbers for integer, float, point*,
    // vector*, normal*, rgb, color, blackbody and spectrum given as (lambda, value) pairs;
    // strings for string, texture and spectrum given by name or file; bools for bool.
    std::vector<double> numbers;
    std::vector<std::string> strings;
    std::vector<uint8_t> bools;
    mutable bool used = false;  // set by whoever reads it, so unused parameters can be reported
};

using ParameterList = std::vector<Parameter>;

}  // namespace candela::pbrt
