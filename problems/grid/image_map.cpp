// Map images (see image_map.hpp). libpng and libnetpbm report errors by longjmp: every call into
// them happens in a small function that sets the jump buffer and holds no C++ object with a
// destructor, so a jump skips only C frames; buffers are allocated by the C++ caller between calls.
#include "problems/grid/image_map.hpp"

#include <pam.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>

#include "framework/error.hpp"

namespace pride::grid {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw InputError(name + ": " + what);
}

std::string dims(std::size_t w, std::size_t h) {
    return std::to_string(w) + " x " + std::to_string(h);
}

/// Refuses sizes before any pixel buffer exists: empty, over kMaxImageCells, or more bytes of
/// pixel data than the file can hold (`max_data` bytes of it).
void check_size(std::size_t w, std::size_t h, double data_bytes, double max_data, const std::string& name) {
    if (w < 1 || h < 1) fail(name, "the image is " + dims(w, h) + " pixels: a map needs at least one");
    if (w > kMaxImageCells || h > kMaxImageCells || w * h > kMaxImageCells)
        fail(name, "the image is " + dims(w, h) + " pixels, more than the " + std::to_string(kMaxImageCells) +
                       " cells a map may have");
    if (data_bytes > max_data)
        fail(name, "truncated or corrupt: the file is too short to hold " + dims(w, h) + " pixels");
}

// ---------------------------------------------------------------------------------------------
// PNG

struct PngState {
    png_structp png = nullptr;
    png_infop info = nullptr;
    const unsigned char* data = nullptr;
    std::size_t size = 0;
    std::size_t pos = 0;
    char message[256] = {};
};

extern "C" void png_read_memory(png_structp png, png_bytep out, png_size_t n) {
    auto* s = static_cast<PngState*>(png_get_io_ptr(png));
    if (n > s->size - s->pos) png_error(png, "the file ends early (truncated)");
    std::memcpy(out, s->data + s->pos, n);
    s->pos += n;
}

extern "C" void png_record_error(png_structp png, png_const_charp message) {
    auto* s = static_cast<PngState*>(png_get_error_ptr(png));
    // libpng puts the name of the chunk it stopped at before its words ("ET[20]h: invalid chunk
    // type"): four bytes of the file, and a message never shows what a file holds. Its words only.
    const char* words = std::strstr(message, ": ");
    if (words && words - message <= 16 &&
        std::memchr(message, ' ', static_cast<std::size_t>(words - message)) == nullptr)
        message = words + 2;
    std::snprintf(s->message, sizeof s->message, "%s", message);
    png_longjmp(png, 1);
}

extern "C" void png_ignore_warning(png_structp, png_const_charp) {}

struct PngHeader {
    png_uint_32 width = 0, height = 0;
    int file_bits = 0;  // bits per pixel in the file
    int channels = 0, bit_depth = 0;
    std::size_t rowbytes = 0;
};

// No C++ objects with destructors below: png_error jumps back here.
bool png_header(PngState& s, PngHeader& h) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_set_read_fn(s.png, &s, png_read_memory);
    png_set_user_limits(s.png, 1u << 24, 1u << 24);
    png_read_info(s.png, s.info);
    h.width = png_get_image_width(s.png, s.info);
    h.height = png_get_image_height(s.png, s.info);
    h.file_bits = png_get_bit_depth(s.png, s.info) * png_get_channels(s.png, s.info);
    png_set_expand(s.png);  // palette to RGB, grey below 8 bits to 8, tRNS to alpha
    png_set_interlace_handling(s.png);
    png_read_update_info(s.png, s.info);
    h.channels = png_get_channels(s.png, s.info);
    h.bit_depth = png_get_bit_depth(s.png, s.info);
    h.rowbytes = png_get_rowbytes(s.png, s.info);
    return true;
}

bool png_pixels(PngState& s, png_bytepp rows) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_read_image(s.png, rows);
    png_read_end(s.png, nullptr);
    return true;
}

// ---------------------------------------------------------------------------------------------
// Netpbm

// libnetpbm keeps its jump buffer and message hooks in globals: one image at a time.
std::mutex netpbm_mutex;
char netpbm_message[256];

extern "C" void netpbm_record_error(const char* message) {
    std::snprintf(netpbm_message, sizeof netpbm_message, "%s", message);
}
extern "C" void netpbm_ignore_message(const char*) {}

struct PnmState {
    std::FILE* file = nullptr;
    struct pam pam {};
    tuple* row = nullptr;
};

// No C++ objects with destructors below: pm_error jumps back here.
bool pnm_header(PnmState& s) {
    jmp_buf jump;
    jmp_buf* saved = nullptr;
    pm_setjmpbufsave(&jump, &saved);
    if (setjmp(jump)) {
        pm_setjmpbuf(saved);
        return false;
    }
    // PAM_STRUCT_SIZE(tuple_type), written with offsetof: the macro takes a member of a null
    // pointer, which UBSan reports.
    pnm_readpaminit(s.file, &s.pam, static_cast<int>(offsetof(struct pam, tuple_type) + sizeof s.pam.tuple_type));
    pm_setjmpbuf(saved);
    return true;
}

bool pnm_pixels(PnmState& s, std::uint16_t* const out) {
    jmp_buf jump;
    jmp_buf* saved = nullptr;
    pm_setjmpbufsave(&jump, &saved);
    if (setjmp(jump)) {
        pm_setjmpbuf(saved);
        return false;
    }
    s.row = pnm_allocpamrow(&s.pam);
    const std::size_t depth = s.pam.depth, width = static_cast<std::size_t>(s.pam.width);
    for (int r = 0; r < s.pam.height; ++r) {
        pnm_readpamrow(&s.pam, s.row);
        std::uint16_t* const line = out + static_cast<std::size_t>(r) * width * depth;
        for (std::size_t x = 0; x < width; ++x)
            for (std::size_t c = 0; c < depth; ++c) line[x * depth + c] = static_cast<std::uint16_t>(s.row[x][c]);
    }
    pm_setjmpbuf(saved);
    return true;
}

}  // namespace

bool is_png(std::string_view bytes) noexcept {
    return bytes.size() >= 8 && bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8);
}

bool is_netpbm(std::string_view bytes) noexcept {
    return bytes.size() >= 3 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7' &&
           (bytes[2] == ' ' || bytes[2] == '\t' || bytes[2] == '\n' || bytes[2] == '\r');
}

Image decode_png(std::string_view bytes, const std::string& name) {
    if (!is_png(bytes)) fail(name, "not a PNG file (no PNG signature)");
    PngState s;
    s.data = reinterpret_cast<const unsigned char*>(bytes.data());
    s.size = bytes.size();
    s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &s, png_record_error, png_ignore_warning);
    if (!s.png) fail(name, "cannot start libpng");
    struct Destroy {
        PngState& s;
        ~Destroy() { png_destroy_read_struct(&s.png, s.info ? &s.info : nullptr, nullptr); }
    } destroy{s};
    s.info = png_create_info_struct(s.png);
    if (!s.info) fail(name, "cannot start libpng");

    PngHeader h;
    if (!png_header(s, h)) fail(name, std::string("bad PNG: ") + s.message);
    // Deflate packs at most 1032 bytes into one: a file shorter than that share of its pixel data
    // (one filter byte per row) is truncated or corrupt, whatever its header says.
    const double data = (static_cast<double>(h.width) * h.file_bits / 8.0 + 1.0) * h.height;
    check_size(h.width, h.height, data, 1032.0 * static_cast<double>(bytes.size()) + 1024.0, name);
    if (h.bit_depth != 8 && h.bit_depth != 16) fail(name, "unsupported PNG bit depth " + std::to_string(h.bit_depth));
    if (h.channels < 1 || h.channels > 4)
        fail(name, "unsupported PNG with " + std::to_string(h.channels) + " channels");

    std::vector<png_byte> buffer(h.rowbytes * h.height);
    std::vector<png_bytep> rows(h.height);
    for (png_uint_32 r = 0; r < h.height; ++r) rows[r] = buffer.data() + r * h.rowbytes;
    if (!png_pixels(s, rows.data())) fail(name, std::string("bad PNG: ") + s.message);

    Image image;
    image.width = static_cast<int>(h.width);
    image.height = static_cast<int>(h.height);
    image.channels = h.channels;
    image.maxval = h.bit_depth == 16 ? 65535 : 255;
    const std::size_t n = std::size_t{h.width} * h.height * static_cast<std::size_t>(h.channels);
    image.samples.resize(n);
    const std::size_t per_row = std::size_t{h.width} * static_cast<std::size_t>(h.channels);
    for (std::size_t r = 0; r < h.height; ++r) {
        const png_byte* p = rows[r];
        std::uint16_t* out = image.samples.data() + r * per_row;
        if (h.bit_depth == 16)
            for (std::size_t k = 0; k < per_row; ++k) out[k] = static_cast<std::uint16_t>(p[2 * k] << 8 | p[2 * k + 1]);
        else
            for (std::size_t k = 0; k < per_row; ++k) out[k] = p[k];
    }
    return image;
}

Image decode_netpbm(std::string_view bytes, const std::string& name) {
    if (!is_netpbm(bytes)) fail(name, "not a Netpbm file (no P1 to P7 magic number)");
    // PAM (P7) is recognised but refused: libnetpbm's PAM header parser leaks a string when it
    // rejects a header (fuzz_image found it), and maps are PGM or PNG.
    if (bytes[1] == '7') fail(name, "PAM (P7) images are not read: save the map as PGM or PNG");
    static std::once_flag init;
    std::call_once(init, [] { pm_init("pride", 0); });
    const std::lock_guard<std::mutex> lock(netpbm_mutex);
    pm_setusererrormsgfn(netpbm_record_error);
    pm_setusermessagefn(netpbm_ignore_message);
    netpbm_message[0] = '\0';

    PnmState s;
    s.file = fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "rb");
    if (!s.file) fail(name, "cannot read the image from memory");
    struct Close {
        PnmState& s;
        ~Close() {
            if (s.row) pnm_freepamrow(s.row);
            std::fclose(s.file);
        }
    } close{s};
    const auto bad = [&] {
        std::string what = netpbm_message;
        while (!what.empty() && (what.back() == '\n' || what.back() == ' ')) what.pop_back();
        for (char& c : what)
            if (c == '\n' || c == '\r') c = ' ';
        fail(name, "bad Netpbm image: " + (what.empty() ? std::string("unreadable") : what));
    };
    if (!pnm_header(s)) bad();
    const auto w = static_cast<std::size_t>(std::max(0, s.pam.width));
    const auto h = static_cast<std::size_t>(std::max(0, s.pam.height));
    // Every format spends at least one bit per pixel (PBM's raw form); the plain forms far more.
    check_size(w, h, static_cast<double>(w) * static_cast<double>(h) / 8.0, static_cast<double>(bytes.size()), name);
    if (s.pam.depth < 1 || s.pam.depth > 4)
        fail(name, "unsupported Netpbm image with " + std::to_string(s.pam.depth) +
                       " planes (1 grey, 2 grey and alpha, 3 RGB, 4 RGBA)");
    if (s.pam.maxval < 1 || s.pam.maxval > 65535) fail(name, "bad Netpbm maxval " + std::to_string(s.pam.maxval));

    Image image;
    image.width = static_cast<int>(w);
    image.height = static_cast<int>(h);
    image.channels = static_cast<int>(s.pam.depth);
    image.maxval = static_cast<unsigned>(s.pam.maxval);
    image.samples.resize(w * h * s.pam.depth);
    if (!pnm_pixels(s, image.samples.data())) bad();
    return image;
}

Image decode_image(std::string_view bytes, const std::string& name) {
    if (is_png(bytes)) return decode_png(bytes, name);
    if (is_netpbm(bytes)) return decode_netpbm(bytes, name);
    fail(name, "not a PNG or Netpbm (PGM, PPM, PBM, PAM) image");
}

CellState pixel_state(const Image& image, std::size_t i, const Occupancy& o) noexcept {
    const std::uint16_t* p = image.samples.data() + i * static_cast<std::size_t>(image.channels);
    const bool colour = image.channels >= 3;
    const double max = image.maxval;
    // As map_server: R, G and B (a grey value three times), and the opacity too in trinary mode.
    double sum = colour ? static_cast<double>(p[0]) + p[1] + p[2] : 3.0 * p[0];
    const double alpha = image.has_alpha() ? p[image.channels - 1] : max;
    int count = 3;
    if (o.mode == MapMode::raw) {
        const double value = std::round(sum / count / max * 255.0);
        if (value > 100.0) return CellState::unknown;
        const double occ = value / 100.0;
        return occ > o.occupied_thresh ? CellState::occupied
               : occ < o.free_thresh   ? CellState::free
                                       : CellState::unknown;
    }
    if (o.mode == MapMode::trinary && image.has_alpha()) {
        sum += alpha;
        ++count;
    }
    if (o.mode == MapMode::scale && alpha != max) return CellState::unknown;
    const double shade = sum / count / max;
    const double occ = o.negate ? shade : 1.0 - shade;
    if (occ > o.occupied_thresh) return CellState::occupied;
    if (occ < o.free_thresh) return CellState::free;
    return CellState::unknown;
}

GridMap image_to_map(const Image& image, const Occupancy& o, const std::string& name) {
    const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    std::vector<std::uint8_t> blocked(n);
    for (std::size_t i = 0; i < n; ++i) {
        const CellState s = pixel_state(image, i, o);
        blocked[i] = s == CellState::occupied || (s == CellState::unknown && !o.unknown_free);
    }
    return GridMap(image.width, image.height, std::move(blocked), name);
}

GridMap parse_image_map(std::string_view bytes, const std::string& name, bool unknown_free) {
    Occupancy o;
    o.unknown_free = unknown_free;
    return image_to_map(decode_image(bytes, name), o, name);
}

}  // namespace pride::grid
