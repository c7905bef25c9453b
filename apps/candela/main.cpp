// candela: the command-line program. Thin by design: one file per subcommand parses its flags
// and calls the library. Exit codes: 0 ok (also when stopped by --time-limit), 2 bad input
// (scene, files, flags, checkpoints), 1 internal error, 130 / 143 stopped by SIGINT / SIGTERM.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <string>

#include "candela/core/error.h"
#include "cli_exit_codes.h"
#include "convert_command.h"
#include "merge_command.h"
#include "render_command.h"

using namespace candela;

int main(int argc, char** argv) {
    CLI::App app{"candela: a physically based Monte Carlo path tracer", "candela"};
    app.set_version_flag("--version", std::string("candela ") + CANDELA_VERSION);
    app.require_subcommand(1);

    cli::RenderArgs render_args;
    CLI::App* render_cmd = cli::add_render_command(app, render_args);
    cli::ConvertArgs convert_args;
    CLI::App* convert_cmd = cli::add_convert_command(app, convert_args);
    cli::MergeArgs merge_args;
    CLI::App* merge_cmd = cli::add_merge_command(app, merge_args);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        fmt::print(stderr, "candela: error: {}\n", e.what());
        return cli::kExitBadInput;
    }

    try {
        if (render_cmd->parsed()) return cli::run_render(render_args);
        if (convert_cmd->parsed()) return cli::run_convert(convert_args);
        if (merge_cmd->parsed()) return cli::run_merge(merge_args);
        return cli::kExitInternal;
    } catch (const SceneError& e) {
        fmt::print(stderr, "candela: error: {}\n", e.what());
        return cli::kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela: internal error: {}\n", e.what());
        return cli::kExitInternal;
    }
}
