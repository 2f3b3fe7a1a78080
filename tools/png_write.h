/* SPDX-License-Identifier: MIT */
/*
 * tools/png_write.h - PNG output for the host programs (the CLI's
 * `vor raster --png`, examples/contours), through stb_image_write from
 * Debian's libstb-dev. It is required, not optional, so a program never
 * silently lacks PNG output: the Makefile installs the package before it
 * builds either program (tools/install-deps.sh cli). Include it from one
 * source file per program: it holds stb's implementation.
 */
#ifndef VOR_TOOLS_PNG_WRITE_H
#define VOR_TOOLS_PNG_WRITE_H

#define STB_IMAGE_WRITE_IMPLEMENTATION
/* stb's code is not written for this project's warning flags */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#endif
