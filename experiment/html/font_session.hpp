#pragma once
// Text drawn with cairo makes cairo and fontconfig cache fonts for the whole process. Pictures
// release those caches when the last one being drawn is done (cairo_debug_reset_static_data,
// FcFini), so that drawing leaves nothing allocated behind (the sanitizer build's LeakSanitizer
// runs the tests). A report of many figures holds one session around all of them and so loads
// the fonts once, not once per figure.
#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include <mutex>

namespace pride::html {

class FontSession {
  public:
    FontSession() {
        const std::lock_guard lock(mutex());
        ++open();
    }
    ~FontSession() {
        // Under the lock: a session opened meanwhile waits until the caches are gone.
        const std::lock_guard lock(mutex());
        if (--open() == 0) {
            cairo_debug_reset_static_data();
            FcFini();
        }
    }
    FontSession(const FontSession&) = delete;
    FontSession& operator=(const FontSession&) = delete;

  private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    static int& open() {
        static int n = 0;
        return n;
    }
};

}  // namespace pride::html
