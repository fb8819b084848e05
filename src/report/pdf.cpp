#include "report/pdf.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"

extern char** environ;

namespace freestand::report {
namespace {

// The converter's standard error quoted in an error message is cut to its last this many
// characters (a Python traceback ends with the reason).
constexpr std::size_t kStderrQuoteChars = 4000;

/// A private folder under the system's temporary folder, removed with its files on scope exit.
class TempFolder {
public:
    TempFolder() {
        std::string templ = (std::filesystem::temp_directory_path() / "freestand-pdf-XXXXXX").string();
        if (::mkdtemp(templ.data()) == nullptr)
            throw IoError(fmt::format("{}: cannot create a temporary folder: {}", templ,
                                      std::strerror(errno)));
        path_ = templ;
    }
    ~TempFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

/// The environment of the converter: this process's, with SOURCE_DATE_EPOCH=0 (fontTools then
/// stamps the font subsets with a fixed time instead of now).
std::vector<std::string> converter_environment() {
    std::vector<std::string> env;
    for (char** e = environ; e != nullptr && *e != nullptr; ++e)
        if (std::strncmp(*e, "SOURCE_DATE_EPOCH=", 18) != 0) env.emplace_back(*e);
    env.emplace_back("SOURCE_DATE_EPOCH=0");
    return env;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (std::string& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

std::string stderr_tail(const std::filesystem::path& file) {
    std::string text;
    try {
        text = core::read_text_file(file);
    } catch (const IoError&) {
        return "";
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    if (text.size() > kStderrQuoteChars) text = "..." + text.substr(text.size() - kStderrQuoteChars);
    return text.empty() ? "" : ":\n" + core::printable(text);
}

/// Runs argv with stdin from /dev/null and stdout and stderr to stderr_file, in its own process
/// group; returns its wait status, or kills the group and throws IoError after time_limit.
int run_bounded(std::vector<std::string> argv, std::vector<std::string> env,
                const std::filesystem::path& stderr_file, std::chrono::milliseconds time_limit) {
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attr;
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, stderr_file.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
    std::vector<char*> c_argv = c_strings(argv);
    std::vector<char*> c_env = c_strings(env);
    pid_t pid = 0;
    const int rc = ::posix_spawn(&pid, c_argv[0], &actions, &attr, c_argv.data(), c_env.data());
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    if (rc != 0)
        throw IoError(fmt::format("cannot run {}: {}", argv[0], std::strerror(rc)));

    const auto deadline = std::chrono::steady_clock::now() + time_limit;
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) return status;
        if (done < 0 && errno != EINTR)
            throw IoError(fmt::format("waiting for {}: {}", argv[0], std::strerror(errno)));
        if (std::chrono::steady_clock::now() >= deadline) {
            ::kill(-pid, SIGKILL);
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            throw IoError(fmt::format("{} did not finish within {} s and was stopped{}", argv[0],
                                      std::chrono::duration<double>(time_limit).count(),
                                      stderr_tail(stderr_file)));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

}  // namespace

std::filesystem::path find_pdf_converter() {
    const char* path_env = std::getenv("PATH");
    const std::string path = path_env != nullptr ? path_env : "";
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find(':', start), path.size());
        const std::string dir = path.substr(start, end - start);
        start = end + 1;
        if (dir.empty()) continue;  // an empty entry would mean the working folder: not searched
        const std::filesystem::path candidate = std::filesystem::path(dir) / pdf_converter_program;
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec) &&
            ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    throw IoError(fmt::format(
        "--pdf needs the program {} (Debian package weasyprint), which is not on PATH ({}); "
        "scripts/setup.sh installs it",
        pdf_converter_program, core::printable(path)));
}

std::string html_to_pdf(const std::filesystem::path& converter, const std::string& html,
                        std::chrono::milliseconds time_limit) {
    const TempFolder tmp;
    const std::filesystem::path html_file = tmp.path() / "report.html";
    const std::filesystem::path pdf_file = tmp.path() / "report.pdf";
    const std::filesystem::path log_file = tmp.path() / "converter.log";
    core::write_new_file(html_file, html);
    const std::string base_url = "file://" + tmp.path().string() + "/";
    const int status = run_bounded({converter.string(), "--encoding", "utf-8",
                                    "--base-url", base_url, html_file.string(), pdf_file.string()},
                                   converter_environment(), log_file, time_limit);
    if (WIFSIGNALED(status))
        throw IoError(fmt::format("{} was killed by signal {}{}", converter.string(),
                                  WTERMSIG(status), stderr_tail(log_file)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw IoError(fmt::format("{} failed with exit code {}{}", converter.string(),
                                  WEXITSTATUS(status), stderr_tail(log_file)));
    std::string pdf;
    try {
        pdf = core::read_text_file(pdf_file);
    } catch (const IoError&) {
        throw IoError(fmt::format("{} wrote no PDF{}", converter.string(), stderr_tail(log_file)));
    }
    if (pdf.rfind("%PDF-", 0) != 0)
        throw IoError(fmt::format("{} wrote a file that is not a PDF{}", converter.string(),
                                  stderr_tail(log_file)));
    return pdf;
}

}  // namespace freestand::report
