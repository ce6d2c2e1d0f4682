#pragma once
// cairo's surfaces written through an OutputFiles::File (framework/output_files.hpp) rather than
// by file name: a figure is then complete or absent like every output, and a write error names
// the file and the system's reason ("No space left on device"), where cairo by name says only
// "error while writing to output stream".
#include <cairo.h>

#include <string>

#include "framework/error.hpp"
#include "framework/output_files.hpp"

namespace pride::html {

/// cairo's write function for a stream into `file` (an OutputFiles::File*).
inline cairo_status_t write_to_file(void* file, const unsigned char* data, unsigned int length) {
    return static_cast<OutputFiles::File*>(file)->append(data, length) ? CAIRO_STATUS_SUCCESS
                                                                       : CAIRO_STATUS_WRITE_ERROR;
}

/// Finishes and destroys `surface` (an SVG stream into `file`, or an image written to it as PNG),
/// then closes `file`. InputError: the file's write error, or cairo's reason for `what`.
inline void finish_into(cairo_surface_t* surface, OutputFiles::File& file, bool png, const std::string& what) {
    cairo_status_t status = cairo_surface_status(surface);
    if (png && status == CAIRO_STATUS_SUCCESS)
        status = cairo_surface_write_to_png_stream(surface, write_to_file, &file);
    cairo_surface_finish(surface);  // an SVG stream writes its document here
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    file.close();  // the file's own failure first: it has the system's reason
    if (status != CAIRO_STATUS_SUCCESS)
        throw InputError(file.path() + ": cannot write " + what + ": " + cairo_status_to_string(status));
}

}  // namespace pride::html
