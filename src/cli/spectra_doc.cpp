// parse_document_options (cli/documents.hpp): option text checked as the command line does, for
// the Python bindings still called with it.
#include <fmt/format.h>

#include "cli/documents.hpp"
#include "core/errors.hpp"

namespace freestand::cli {

po::variables_map parse_document_options(const std::string& command,
                                         const po::options_description& desc,
                                         const std::vector<std::string>& args) {
    for (const std::string& a : args)
        if (a == "--help" || a == "-h")
            throw UsageError(fmt::format("{}: --help is not an option here", command));
    return *parse_options(command, "", desc, args);
}

}  // namespace freestand::cli
