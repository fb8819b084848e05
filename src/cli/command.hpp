#pragma once
/// Subcommand registry: each cmd_*.cpp registers itself with a static CommandRegistrar, so
/// adding a command never touches main.cpp.
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace freestand::cli {

/// A subcommand. run() gets the arguments after the command name and returns the exit code;
/// it throws freestand::Error for anything the user must fix.
struct Command {
    std::string name;
    std::string summary;  ///< one line for `freestand --help`
    std::function<int(const std::vector<std::string>& args)> run;
};

/// Registered commands by name (sorted, so --help lists them deterministically).
std::map<std::string, Command>& command_table();

struct CommandRegistrar {
    explicit CommandRegistrar(Command command);
};

}  // namespace freestand::cli
