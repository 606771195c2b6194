#include "batch/worker_pool.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <string_view>

#include "batch/worker.hpp"
#include "engine/core/types.hpp"

namespace tubemesh::batch {

using Clock = std::chrono::steady_clock;

struct WorkerPool::Worker {
    std::uint64_t tag = 0;
    pid_t pid = -1;
    int result_fd = -1, error_fd = -1;
    std::string result, error;  // what the worker wrote to each
    Clock::time_point deadline = Clock::time_point::max();
    double time_limit = 0;
    bool timed_out = false;
};

namespace {

// Keeps the end of a worker's stderr: the last lines say where a crash came from.
constexpr std::size_t kErrorTail = 4096;

void close_fd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

// Reads what is there; false at end of file.
bool drain(int fd, std::string& into, std::size_t keep) {
    char buffer[65536];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) return true;
    if (n <= 0) return false;
    into.append(buffer, static_cast<std::size_t>(n));
    if (keep > 0 && into.size() > 2 * keep) into.erase(0, into.size() - keep);
    return true;
}

std::string last_line(std::string_view text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
    const auto nl = text.rfind('\n');
    return std::string(nl == std::string_view::npos ? text : text.substr(nl + 1));
}

// In the child between fork and exec: async-signal-safe calls only.
[[noreturn]] void exec_worker(char* const argv[], int in, int result, int error, int null_fd, pid_t parent) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the parent died before prctl took effect
    ::signal(SIGPIPE, SIG_DFL);
    if (::dup2(in, 0) < 0 || ::dup2(null_fd, 1) < 0 || ::dup2(error, 2) < 0 || ::dup2(result, kResultFd) < 0)
        ::_exit(127);
    ::execv(argv[0], argv);
    ::_exit(127);
}

nlohmann::json outcome_of(const WorkerPool::Worker& w, int status);

}  // namespace

WorkerPool::WorkerPool(WorkerCommand command) : command_(std::move(command)) {
    // A worker that dies before reading its request must not take the batch down with it.
    ::signal(SIGPIPE, SIG_IGN);
}

WorkerPool::~WorkerPool() {
    for (Worker& w : workers_) {
        ::kill(w.pid, SIGKILL);
        ::waitpid(w.pid, nullptr, 0);
        close_fd(w.result_fd);
        close_fd(w.error_fd);
    }
}

std::size_t WorkerPool::running() const { return workers_.size(); }

void WorkerPool::start(std::uint64_t tag, const nlohmann::json& request, double time_limit) {
    int in[2], result[2], error[2];
    if (::pipe2(in, O_CLOEXEC) != 0) throw Error(std::string("cannot start a worker: ") + std::strerror(errno));
    if (::pipe2(result, O_CLOEXEC) != 0 || ::pipe2(error, O_CLOEXEC) != 0)
        throw Error(std::string("cannot start a worker: ") + std::strerror(errno));
    const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);

    std::vector<std::string> args = {command_.program};
    args.insert(args.end(), command_.args.begin(), command_.args.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) exec_worker(argv.data(), in[0], result[1], error[1], null_fd, parent);
    ::close(in[0]);
    ::close(result[1]);
    ::close(error[1]);
    ::close(null_fd);
    if (pid < 0) {
        ::close(in[1]);
        ::close(result[0]);
        ::close(error[0]);
        throw Error(std::string("cannot start a worker: ") + std::strerror(errno));
    }

    // The request is small (a pipe holds 64 KiB); a worker that died early gives EPIPE, and
    // its outcome says so.
    const std::string text = request.dump();
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(in[1], text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
    ::close(in[1]);

    Worker w;
    w.tag = tag;
    w.pid = pid;
    w.result_fd = result[0];
    w.error_fd = error[0];
    w.time_limit = time_limit;
    if (time_limit > 0)
        w.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(time_limit));
    workers_.push_back(std::move(w));
}

std::vector<WorkerOutcome> WorkerPool::wait(int timeout_ms) {
    std::vector<WorkerOutcome> ended;
    if (workers_.empty()) return ended;
    const auto now = Clock::now();
    auto limit = timeout_ms < 0 ? Clock::time_point::max() : now + std::chrono::milliseconds(timeout_ms);
    for (const Worker& w : workers_)
        if (!w.timed_out) limit = std::min(limit, w.deadline);
    int wait_ms = -1;
    if (limit != Clock::time_point::max())
        wait_ms = static_cast<int>(std::max<long long>(
            0, std::chrono::ceil<std::chrono::milliseconds>(limit - now).count()));

    std::vector<pollfd> fds;
    for (const Worker& w : workers_) {
        if (w.result_fd >= 0) fds.push_back({w.result_fd, POLLIN, 0});
        if (w.error_fd >= 0) fds.push_back({w.error_fd, POLLIN, 0});
    }
    if (::poll(fds.data(), fds.size(), wait_ms) < 0 && errno != EINTR)
        throw Error(std::string("batch: poll failed: ") + std::strerror(errno));

    for (const pollfd& p : fds) {
        if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
        for (Worker& w : workers_) {
            if (p.fd == w.result_fd && !drain(w.result_fd, w.result, 0)) close_fd(w.result_fd);
            if (p.fd == w.error_fd && !drain(w.error_fd, w.error, kErrorTail)) close_fd(w.error_fd);
        }
    }
    const auto after = Clock::now();
    for (Worker& w : workers_)
        if (!w.timed_out && after >= w.deadline) {
            ::kill(w.pid, SIGKILL);
            w.timed_out = true;
        }

    for (auto it = workers_.begin(); it != workers_.end();) {
        int status = 0;
        // Both pipes closed means the worker is gone or going: reap it.
        const bool closed = it->result_fd < 0 && it->error_fd < 0;
        if (!closed || ::waitpid(it->pid, &status, 0) != it->pid) {
            ++it;
            continue;
        }
        ended.push_back({it->tag, outcome_of(*it, status)});
        it = workers_.erase(it);
    }
    return ended;
}

namespace {

nlohmann::json outcome_of(const WorkerPool::Worker& w, int status) {
    if (w.timed_out)
        return {{"status", "failed"},
                {"timed_out", true},
                {"error", "no result within the time limit of " + std::to_string(static_cast<long long>(w.time_limit)) +
                              " s: the worker was killed (raise --time-limit if the block is just large)"}};
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        try {
            return nlohmann::json::parse(w.result);
        } catch (const std::exception&) {
        }
    }
    std::string why = WIFSIGNALED(status) ? std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                                                ::strsignal(WTERMSIG(status)) + ")"
                                          : "exited with status " + std::to_string(WEXITSTATUS(status)) + " and no result";
    const std::string tail = last_line(w.error);
    if (!tail.empty()) why += "; its last message: " + tail;
    return {{"status", "crashed"}, {"error", "the worker " + why}};
}

}  // namespace

}  // namespace tubemesh::batch
