// The module's calls in progress (common.hpp, Call): Ctrl-C on the main thread, and the
// interpreter's exit waiting for every other thread to leave the module's C++ frames.
#include <chrono>
#include <condition_variable>
#include <vector>

#include "common.hpp"

namespace pride::python {

namespace {

// Read and written with the GIL held only (calls are made and destroyed with it, the atexit hook
// runs with it), which orders them.
std::vector<Call*> calls;
bool exiting = false;
thread_local Call* innermost = nullptr;

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

Call& Call::current() {
    if (!innermost) throw std::logic_error("pride: a binding without its Call guard");
    return *innermost;
}

void Call::run_work(const std::function<void()>& work, const std::function<void()>& stop, bool poll) {
    if (reason_) std::rethrow_exception(reason_);  // stopped before its work began
    stop_ = stop;
    struct Clear {
        std::function<void()>& f;
        ~Clear() { f = nullptr; }
    } clear{stop_};
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
