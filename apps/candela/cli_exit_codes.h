#pragma once
// The program's exit codes, shared by its subcommands.
namespace candela::cli {

constexpr int kExitBadInput = 2;  // the scene, a file it names, a flag or a checkpoint
constexpr int kExitInternal = 1;  // a bug: anything but bad input

}  // namespace candela::cli
