#pragma once
// The adapt subcommand's options (AdaptCommand.cpp); main.cpp adds the sizing options
// shared with mesh and sizing (γ_a defaults to 10 here) and runs cli::runAdapt.
#include <CLI/CLI.hpp>

#include "tools/cli/Commands.h"

namespace aniso::cli {

CLI::App* addAdaptCommand(CLI::App& app, AdaptOptions& options);

}  // namespace aniso::cli
