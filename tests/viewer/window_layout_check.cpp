// The panel beside the picture, not over it: the whole window's screenshot
// (facet view --with-panel) holds the 3D view's screenshot byte for byte in
// its right part, and something else (the panel) on its left; with the
// panel hidden the window is the 3D view alone.
// Usage: window_layout_check WINDOW.png VIEW.png panel|no-panel
#include <cstdio>
#include <cstring>
#include <exception>

#include "image/png.h"

using namespace facet;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: window_layout_check WINDOW.png VIEW.png panel|no-panel\n");
    return 64;
  }
  try {
    const Image window = readPng(argv[1]), view = readPng(argv[2]);
    const bool panel = std::strcmp(argv[3], "panel") == 0;
    const int left = window.width() - view.width();
    if (window.height() != view.height() || left < 0 || (panel ? left == 0 : left != 0)) {
      std::fprintf(stderr, "the window is %dx%d, the view %dx%d: expected the view's height and %s\n", window.width(), window.height(), view.width(),
                   view.height(), panel ? "a panel's width more" : "the same width");
      return 1;
    }
    long differing = 0;
    for (int y = 0; y < view.height(); ++y)
      for (int x = 0; x < view.width(); ++x) {
        const Rgba8 a = window.at(left + x, y), b = view.at(x, y);
        if (a.r != b.r || a.g != b.g || a.b != b.b) ++differing;
      }
    if (differing > 0) {
      std::fprintf(stderr, "%ld pixels of the window's 3D view differ from the view's screenshot: something covers the picture\n", differing);
      return 1;
    }
    if (panel) {
      long panelPixels = 0;  // not the background's black
      for (int y = 0; y < window.height(); ++y)
        for (int x = 0; x < left; ++x) {
          const Rgba8 p = window.at(x, y);
          if (p.r + p.g + p.b > 60) ++panelPixels;
        }
      if (panelPixels < left * window.height() / 100) {
        std::fprintf(stderr, "the %d columns left of the view hold %ld drawn pixels: no panel\n", left, panelPixels);
        return 1;
      }
      std::printf("panel %d px wide beside the %dx%d view, %ld of its pixels drawn; the view is untouched\n", left, view.width(), view.height(),
                  panelPixels);
    } else {
      std::printf("no panel: the window is the %dx%d view\n", view.width(), view.height());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
