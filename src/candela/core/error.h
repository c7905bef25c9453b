#pragma once
// Errors in user input (scene files, meshes, images, command-line values). They carry where the
// problem is so the CLI can print one line `FILE:LINE:COL: /json/pointer: message` and exit 2.
#include <stdexcept>
#include <string>

namespace candela {

struct SourceLocation {
    std::string file;          // as the user named it; empty when not from a file
    int line = 0;              // 1-based; 0 when unknown
    int column = 0;            // 1-based; 0 when unknown
    std::string json_pointer;  // RFC 6901 pointer into a JSON scene, e.g. "/shapes/3/radius"
};

class SceneError : public std::runtime_error {
  public:
    SceneError(SourceLocation where, std::string message);
    const SourceLocation& where() const { return where_; }
    const std::string& message() const { return message_; }
    // "file:line:col: /pointer: message", leaving out the parts that are unknown.
    std::string formatted() const;

  private:
    SourceLocation where_;
    std::string message_;
};

// Throw a SceneError located at `file` (and `line`, for formats that have lines): how the readers
// of mesh and volume files (PLY, NanoVDB, OpenVDB) report a bad file.
[[noreturn]] void fail_in_file(const std::string& file, const std::string& message);
[[noreturn]] void fail_in_file(const std::string& file, int line, const std::string& message);

// A failure that is not the user's input: an internal error (CLI exit code 1).
class RenderError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace candela
