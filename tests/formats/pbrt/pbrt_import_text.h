#pragma once
// pbrt-v4 text imported as if it were the file tests/data/pbrt/inline.pbrt (so that relative file
// names find the fixtures there), and the located error importing it throws: what the importer's
// tests share.
#include <filesystem>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_importer.h"

namespace candela::pbrt::test {

inline const std::filesystem::path kInlineFile = std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt" / "inline.pbrt";

inline ImportedScene import(const std::string& text) { return import_pbrt_string(text, kInlineFile); }

// "file:line:col: message" of the error importing `text`; "no error" when it imports.
inline std::string import_error(const std::string& text) {
    try {
        import(text);
    } catch (const SceneError& e) {
        return e.formatted();
    }
    return "no error";
}

}  // namespace candela::pbrt::test
