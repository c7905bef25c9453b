#pragma once
// Where a token of a pbrt-v4 scene is: file, line, column, and the chain of Include/Import
// directives that led to the file, so that an error reads
// `geometry/killeroo.pbrt:12:5: message (included from killeroo-simple.pbrt:42:5)`.
#include <memory>
#include <string>

#include "candela/core/error.h"

namespace candela::pbrt {

struct IncludeSite;

struct Location {
    std::string file;  // as the scene or the Include named it, relative to the working folder
    int line = 0;      // 1-based
    int column = 0;    // 1-based, in bytes
    std::shared_ptr<const IncludeSite> included_from;  // null in the main file
};

struct IncludeSite {
    Location location;  // of the Include/Import directive
};

// "file:line:col" with " (included from ...)" for each level of the chain.
std::string describe(const Location& at);
// A SceneError at `at`: the message gets the include chain appended.
[[noreturn]] void fail(const Location& at, const std::string& message);

}  // namespace candela::pbrt
