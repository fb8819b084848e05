/// freestand: thin command-line front end. Parses the command name, dispatches to a registered
/// command, and maps errors to exit codes (README "Exit codes").
#include <exception>
#include <fmt/format.h>
#include <iostream>
#include <string>
#include <vector>

#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/flag_names.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "core/version.hpp"

namespace freestand::cli {

std::map<std::string, Command>& command_table() {
    static std::map<std::string, Command> table;
    return table;
}

CommandRegistrar::CommandRegistrar(Command command) {
    command_table().emplace(command.name, std::move(command));
}

namespace {

void print_help() {
    std::cout << "freestand " << core::version() <<
                 " - must free-standing equipment be anchored to survive the design earthquake?\n\n"
                 "usage: freestand COMMAND [options]   (freestand COMMAND --help for its options)\n\n"
                 "commands:\n";
    for (const auto& [name, cmd] : command_table())
        std::cout << fmt::format("  {:<10} {}\n", name, cmd.summary);
    std::cout << "\nfreestand --version: version, commit and the versions of the linked libraries\n";
    std::cout << "\nexit codes: 0 ok, 1 a check failed, 2 usage, 3 bad input, 4 numerical failure,"
                 " 5 file I/O, 70 internal error\n";
}

}  // namespace
}  // namespace freestand::cli

int main(int argc, char** argv) {
    using namespace freestand;
    const std::vector<std::string> all(argv + 1, argv + argc);
    if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
        cli::print_help();
        return all.empty() ? static_cast<int>(ExitCode::usage) : 0;
    }
    if (all[0] == "--version") {
        std::cout << cli::version_text();
        return 0;
    }
    // Messages quote the user's arguments and the bytes of their files: control characters
    // (a terminal's escape sequences) are shown as \xNN, never sent raw.
    using core::printable;
    const auto it = cli::command_table().find(all[0]);
    if (it == cli::command_table().end()) {
        std::cerr << "freestand: unknown command \"" << printable(all[0])
                  << "\" (see freestand --help)\n";
        return static_cast<int>(ExitCode::usage);
    }
    try {
        return it->second.run(std::vector<std::string>(all.begin() + 1, all.end()));
    } catch (const InputError& e) {
        std::cerr << "freestand " << all[0] << ": error: "
                  << printable(cli::on_command_line(e).what()) << "\n";
        return static_cast<int>(e.code());
    } catch (const Error& e) {
        std::cerr << "freestand " << all[0] << ": error: " << printable(e.what()) << "\n";
        return static_cast<int>(e.code());
    } catch (const std::exception& e) {
        std::cerr << "freestand " << all[0] << ": internal error: " << printable(e.what())
                  << "\n";
        return static_cast<int>(ExitCode::internal);
    }
}
