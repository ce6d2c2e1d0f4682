// The module's calls in progress (common.hpp, Call): Ctrl-C on the main thread, and the
// interpreter's exit waiting for every other thread to leave the module's C++ frames.
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <vector>

#include "common.hpp"

namespace pride::python {

namespace {

// Read and written with the GIL held only (calls are made and destroyed with it, the atexit hook
// runs with it), which orders them.
std::vector<Call*> calls;
bool exiting = false;
thread_local Call* innermost = nullptr;

// Ctrl-C on a main-thread run that calls no Python, under Python's default SIGINT handler: a
// signal handler in front of Python's sets the run's stop flag (read once per iteration) and
// calls Python's, whose KeyboardInterrupt the call raises once the run has stopped. No thread is
// started (a helper thread cost 0.2 ms a call, three times a small run). Main thread only, so
// these are written by one thread; the handler reads them.
std::atomic<std::atomic<bool>*> sigint_flag{nullptr};
struct sigaction python_sigint {};
int sigint_depth = 0;

extern "C" void stop_on_sigint(int signal) {
    if (std::atomic<bool>* flag = sigint_flag.load()) flag->store(true);
    if (python_sigint.sa_handler != SIG_DFL && python_sigint.sa_handler != SIG_IGN) python_sigint.sa_handler(signal);
}

/// True when SIGINT's Python handler is the default one (it raises KeyboardInterrupt).
bool default_sigint() {
    static const auto* signal_module = new py::object(py::module_::import("signal"));  // kept past finalisation
    return signal_module->attr("getsignal")(SIGINT).is(signal_module->attr("default_int_handler"));
}

/// The handler in front of Python's while a main-thread run works; nested runs stop the innermost.
class SigintStops {
  public:
    explicit SigintStops(std::atomic<bool>* flag) : outer_(sigint_flag.exchange(flag)) {
        if (sigint_depth++ > 0) return;
        struct sigaction ours {};
        sigaction(SIGINT, nullptr, &python_sigint);
        // A handler taking siginfo is not Python's: it is left alone (Ctrl-C then waits for the run).
        if (python_sigint.sa_flags & SA_SIGINFO) return;
        ours = python_sigint;
        ours.sa_flags &= ~SA_SIGINFO;
        ours.sa_handler = stop_on_sigint;
        sigaction(SIGINT, &ours, nullptr);
    }
    ~SigintStops() {
        sigint_flag.store(outer_);
        if (--sigint_depth > 0) return;
        // Unless the run's own Python code installed another handler meanwhile.
        struct sigaction now {};
        sigaction(SIGINT, nullptr, &now);
        if (now.sa_handler == stop_on_sigint) sigaction(SIGINT, &python_sigint, nullptr);
    }
    SigintStops(const SigintStops&) = delete;
    SigintStops& operator=(const SigintStops&) = delete;

  private:
    std::atomic<bool>* outer_;
};

unsigned long main_thread_ident() {
    static const unsigned long ident =
        py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
    return ident;
}

}  // namespace

bool on_main_thread() {
    return PyThread_get_thread_ident() == main_thread_ident();
}

Call::Call() : thread_(std::this_thread::get_id()), outer_(innermost) {
    // The main thread runs the exit itself (later atexit hooks may use the module); another
    // thread would start work the exit has no more time to wait for.
    if (exiting && !on_main_thread()) throw Exiting{};
    calls.push_back(this);
    innermost = this;
}

Call::~Call() {
    innermost = outer_;
    std::erase(calls, this);
}

bool Call::alone() {
    return calls.size() <= 1;
}

Call& Call::current() {
    if (!innermost) throw std::logic_error("pride: a binding without its Call guard");
    return *innermost;
}

void Call::run_work(const std::function<void()>& work, const std::function<void()>& stop, bool poll,
                    std::atomic<bool>* flag) {
    if (reason_) std::rethrow_exception(reason_);  // stopped before its work began
    stop_ = stop;
    struct Clear {
        std::function<void()>& f;
        ~Clear() { f = nullptr; }
    } clear{stop_};
    if (poll && flag && on_main_thread() && default_sigint()) {
        try {
            const SigintStops sigint(flag);
            py::gil_scoped_release release;
            work();
        } catch (...) {
            if (!reason_ && PyErr_CheckSignals() == 0) throw;
            if (!reason_) reason_ = std::make_exception_ptr(py::error_already_set());
        }
        if (!reason_ && PyErr_CheckSignals() != 0) reason_ = std::make_exception_ptr(py::error_already_set());
        if (reason_) std::rethrow_exception(reason_);
        return;
    }
    if (!poll || !on_main_thread()) {
        try {
            py::gil_scoped_release release;
            work();
        } catch (...) {
            if (!reason_) throw;
        }
        if (reason_) std::rethrow_exception(reason_);
        return;
    }
    std::mutex mutex;
    std::condition_variable ended;
    bool finished = false;
    std::exception_ptr failure;
    std::thread helper([&] {
        try {
            work();
        } catch (...) {
            failure = std::current_exception();
        }
        {
            const std::lock_guard lock(mutex);
            finished = true;
        }
        ended.notify_all();
    });
    const auto join = [&] {
        py::gil_scoped_release release;
        helper.join();
    };
    try {
        for (bool done = false; !done;) {
            {
                py::gil_scoped_release release;
                std::unique_lock lock(mutex);
                done = ended.wait_for(lock, std::chrono::milliseconds(20), [&] { return finished; });
            }
            if (!done && !reason_ && PyErr_CheckSignals() != 0) {
                reason_ = std::make_exception_ptr(py::error_already_set());
                stop();
            }
        }
    } catch (...) {
        // Only the exception's own capture can throw here; the helper is never left running.
        stop();
        join();
        throw;
    }
    join();
    if (reason_) std::rethrow_exception(reason_);
    if (failure) std::rethrow_exception(failure);
}

void stop_calls_at_exit() {
    exiting = true;
    const auto me = std::this_thread::get_id();
    for (;;) {
        bool others = false;
        for (Call* c : calls) {
            if (c->thread_ == me) continue;
            others = true;
            if (!c->reason_) {
                c->reason_ = std::make_exception_ptr(Exiting{});
                if (c->stop_) c->stop_();
            }
        }
        if (!others) return;
        py::gil_scoped_release release;  // the calls take the GIL to return
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

}  // namespace pride::python
