// libFuzzer target: pbrt-v4 scene text through the parser (pbrt_parser.h), with a target that
// only looks at what it is handed. A SceneError is the expected answer to bad input; anything
// else escaping, a crash, a sanitizer report or a parameter that breaks the parser's promises
// (values of one kind only, the kind its type holds; finite numbers; whole points and pairs) is
// a bug. The text is parsed as a file in tests/data/pbrt/, so Include can reach the fixtures.
#include <cmath>
#include <cstdint>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_null_target.h"
#include "candela/formats/pbrt/pbrt_parser.h"
#include "fuzz_support.h"

namespace {

using candela::fuzz::require;

struct TouchingTarget : candela::pbrt::NullTarget {
    double sum = 0;
    void parameters(const candela::pbrt::ParameterList& list) override {
        for (const candela::pbrt::Parameter& p : list) {
            const int kinds = !p.numbers.empty() + !p.strings.empty() + !p.bools.empty();
            require(kinds <= 1, "a parameter holds values of one kind");
            require(!p.type.empty() && !p.name.empty(), "a parameter has a type and a name");
            require(p.location.line > 0 && p.location.column > 0, "a parameter is located");
            for (const double x : p.numbers) {
                require(std::isfinite(x), "numbers are finite");
                sum += x;
            }
            for (const auto& s : p.strings) sum += double(s.size());
            for (const uint8_t b : p.bools) sum += b;
            const bool numeric = p.type != "string" && p.type != "texture" && p.type != "bool" && p.type != "spectrum";
            if (numeric) require(p.strings.empty() && p.bools.empty(), "numeric types hold numbers");
            if (p.type == "point3" || p.type == "normal" || p.type == "rgb")
                require(p.numbers.size() % 3 == 0, "whole triples");
            if (p.type == "integer")
                for (const double x : p.numbers) require(x == std::floor(x), "integers are whole");
        }
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    TouchingTarget target;
    try {
        candela::pbrt::parse_string(text, CANDELA_FUZZ_PBRT_DIR "/fuzz.pbrt", target);
    } catch (const candela::SceneError&) {
    }
    return 0;
}
