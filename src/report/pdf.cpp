#include "report/pdf.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/text_parse.hpp"

extern char** environ;

namespace freestand::report {
namespace {

// The converter's standard error quoted in an error message is cut to its last this many
// characters (a Python traceback ends with the reason).
constexpr std::size_t kStderrQuoteChars = 4000;

/// Prefix of the temporary folders: "freestand-pdf-<pid>-XXXXXX", so a later run can tell a
/// folder whose process died (killed beyond any handler, SIGKILL) from one in use.
std::string temp_prefix() { return "freestand-pdf-"; }

/// Removes the temporary folders of runs that died.
void remove_dead_temp_folders() {
    std::error_code ec;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::temp_directory_path(ec), ec)) {
        if (core::left_by_dead_process(entry.path().filename().string(), temp_prefix()))
            std::filesystem::remove_all(entry.path(), ec);
    }
}

/// A private folder under the system's temporary folder, removed with its files on scope exit.
class TempFolder {
public:
    TempFolder() {
        std::string templ = (std::filesystem::temp_directory_path() /
                             fmt::format("{}{}-XXXXXX", temp_prefix(), ::getpid()))
                                .string();
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

/// The signals that stop a run from outside: Ctrl-C (SIGINT to the terminal's foreground
/// process group, which the converter's own group is not in), timeout(1)'s and kill's SIGTERM,
/// a closed terminal's SIGHUP.
constexpr std::array<int, 3> kStopSignals{SIGINT, SIGTERM, SIGHUP};

volatile std::sig_atomic_t stop_signal_noted = 0;

extern "C" void note_stop_signal(int signal) { stop_signal_noted = signal; }

/// While alive, a stop signal is noted instead of acted on, so the conversion can stop the
/// converter and remove its folder first; then restore() and act_on_noted() give the signal
/// to the disposition the process had (by default it ends the process: a shell shows 128 +
/// signal). A signal the process ignores (nohup's SIGHUP, a background job's SIGINT) stays
/// ignored.
class StopSignalGuard {
public:
    StopSignalGuard() {
        stop_signal_noted = 0;
        struct sigaction note {};
        note.sa_handler = note_stop_signal;
        sigemptyset(&note.sa_mask);
        for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
            ::sigaction(kStopSignals[i], nullptr, &previous_[i]);
            if (previous_[i].sa_handler != SIG_IGN) ::sigaction(kStopSignals[i], &note, nullptr);
        }
    }
    ~StopSignalGuard() { restore(); }
    StopSignalGuard(const StopSignalGuard&) = delete;
    StopSignalGuard& operator=(const StopSignalGuard&) = delete;

    static int noted() { return stop_signal_noted; }
    void restore() {
        for (std::size_t i = 0; i < kStopSignals.size(); ++i)
            ::sigaction(kStopSignals[i], &previous_[i], nullptr);
    }
    /// Restores the process's dispositions and raises the noted signal; when that does not end
    /// the process (a handler of the embedding process returned), the run stops with IoError.
    [[noreturn]] void act_on_noted(const std::filesystem::path& converter) {
        const int signal = noted();
        restore();
        ::raise(signal);
        throw IoError(fmt::format("{}: stopped by signal {} ({})", converter.string(), signal,
                                  strsignal(signal)));
    }

private:
    std::array<struct sigaction, kStopSignals.size()> previous_{};
};

/// One conversion at a time: the stop-signal dispositions are the process's.
std::mutex conversion_mutex;

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

/// Starts argv with stdin from /dev/null and stdout and stderr to stderr_file, in a process
/// group of its own (the group is killed as a whole: a converter may start children) that gets
/// SIGKILL if this thread dies first (PR_SET_PDEATHSIG, Linux: the guard for a SIGKILL of
/// freestand, which no handler sees). Throws IoError when it cannot be started.
pid_t start_converter(const std::vector<char*>& argv, const std::vector<char*>& env,
                      const std::filesystem::path& stderr_file) {
    // exec's failure reaches the parent through a pipe that exec closes (O_CLOEXEC).
    int report[2];
    if (::pipe2(report, O_CLOEXEC) != 0)
        throw IoError(fmt::format("cannot run {}: {}", argv[0], std::strerror(errno)));
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec: the process may have threads.
        ::close(report[0]);
        ::setpgid(0, 0);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) ::_exit(127);  // the parent died before prctl
        const int in = ::open("/dev/null", O_RDONLY);
        const int out = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (in < 0 || out < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(out, 2) < 0) {
            const int err = errno;
            (void)!::write(report[1], &err, sizeof err);
            ::_exit(127);
        }
        ::execve(argv[0], argv.data(), env.data());
        const int err = errno;
        (void)!::write(report[1], &err, sizeof err);
        ::_exit(127);
    }
    const int fork_errno = errno;
    ::close(report[1]);
    if (pid < 0) {
        ::close(report[0]);
        throw IoError(fmt::format("cannot run {}: {}", argv[0], std::strerror(fork_errno)));
    }
    // Also from here, so the group exists before any kill(-pid) (the child may not have run).
    ::setpgid(pid, pid);
    int exec_errno = 0;
    ssize_t n = 0;
    while ((n = ::read(report[0], &exec_errno, sizeof exec_errno)) < 0 && errno == EINTR) {
    }
    ::close(report[0]);
    if (n == static_cast<ssize_t>(sizeof exec_errno)) {
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        throw IoError(fmt::format("cannot run {}: {}", argv[0], std::strerror(exec_errno)));
    }
    return pid;
}

/// Kills the converter's process group and reaps the converter.
int stop_group(pid_t pid) {
    ::kill(-pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

/// Runs argv (see start_converter); returns its wait status, or kills its group and throws
/// IoError after time_limit or when a stop signal is noted (StopSignalGuard).
int run_bounded(std::vector<std::string> argv, std::vector<std::string> env,
                const std::filesystem::path& stderr_file, std::chrono::milliseconds time_limit) {
    const std::vector<char*> c_argv = c_strings(argv);
    const std::vector<char*> c_env = c_strings(env);
    const pid_t pid = start_converter(c_argv, c_env, stderr_file);
    const auto deadline = std::chrono::steady_clock::now() + time_limit;
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) return status;
        if (done < 0 && errno != EINTR) {
            const int err = errno;
            stop_group(pid);
            throw IoError(fmt::format("waiting for {}: {}", argv[0], std::strerror(err)));
        }
        if (StopSignalGuard::noted() != 0) {
            stop_group(pid);
            throw IoError(fmt::format("{} was stopped by signal {}", argv[0],
                                      static_cast<int>(StopSignalGuard::noted())));
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            stop_group(pid);
            throw IoError(fmt::format("{} did not finish within {} s and was stopped{}", argv[0],
                                      std::chrono::duration<double>(time_limit).count(),
                                      stderr_tail(stderr_file)));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

/// The conversion proper, in its temporary folder (removed when this returns or throws).
std::string convert(const std::filesystem::path& converter, const std::string& html,
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

}  // namespace

std::filesystem::path find_pdf_converter() {
    const char* path_env = std::getenv("PATH");
    const std::string path = path_env != nullptr ? path_env : "";
    for (const std::string& dir : core::text::split(path, ':')) {
        if (dir.empty()) continue;  // an empty entry would mean the working folder: not searched
        const std::filesystem::path candidate = std::filesystem::path(dir) / pdf_converter_program;
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec) &&
            ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    throw IoError(fmt::format(
        "report.pdf needs the program {} (Debian package weasyprint), which is not on PATH ({}); "
        "scripts/setup.sh installs it",
        pdf_converter_program, core::printable(path)));
}

std::string html_to_pdf(const std::filesystem::path& converter, const std::string& html,
                        std::chrono::milliseconds time_limit) {
    const std::lock_guard<std::mutex> lock(conversion_mutex);
    remove_dead_temp_folders();
    StopSignalGuard guard;
    std::string pdf;
    try {
        pdf = convert(converter, html, time_limit);
    } catch (...) {
        if (StopSignalGuard::noted() == 0) throw;
    }
    // A stop signal during the conversion acts now, the converter stopped and its folder gone.
    if (StopSignalGuard::noted() != 0) guard.act_on_noted(converter);
    return pdf;
}

}  // namespace freestand::report
