#pragma once
// Which channels an image file stores. An Image is always RGBA8: a grey
// file fills R = G = B, and a file without alpha reads as opaque (A = 255).
// What the file stores is what OpenImageIO's idiff compares, and averages
// its mean and RMS error over: from 1 channel (grey) to 4 (RGBA).
namespace facet {

struct StoredChannels {
  bool colour = true;  // R, G, B; false: one grey channel, Y (R = G = B in the Image)
  bool alpha = true;   // false: the file has no alpha (A = 255 in the Image)

  int count() const { return (colour ? 3 : 1) + (alpha ? 1 : 0); }
  friend bool operator==(const StoredChannels&, const StoredChannels&) = default;
};

// Two files side by side: colour when either has colour, alpha when either
// has alpha.
inline StoredChannels unionOf(StoredChannels a, StoredChannels b) { return {a.colour || b.colour, a.alpha || b.alpha}; }

}  // namespace facet
