#pragma once
// facet render's -o as a template of file names, as F3D's --output is:
//   {scene}            the scene file's name without its extension (a.nii.gz: a),
//                      or the builtin's name (none: default)
//   {backend}          gl, cpu, reference or ray
//   {frame}, {n}       the frame's number from 0, zero-padded to the digits of
//                      the last one (--turntable 36: 00 to 35), so names sort
//   {frame:W}, {n:W}   at least W digits (W 1 to 9), as F3D's {frame:4}
//   {{, }}             a brace
// Unlike F3D's {n} (the first number no file has yet), facet's is the frame:
// a run writes the same names again.
#include <string>
#include <vector>

namespace facet {

struct TemplateValues {
  std::string scene;    // {scene}
  std::string backend;  // {backend}
};

class OutputTemplate {
 public:
  // Parses `pattern`; throws facet::UsageError naming `option`, the pattern
  // and the fault: an unknown {placeholder}, a brace without its partner, a
  // width that is not 1 to 9.
  OutputTemplate(const std::string& pattern, const std::string& option);

  // Whether a frame number is in the name ({frame} or {n}): without one,
  // every frame of a turntable would have the same name.
  bool numbersFrames() const;

  // The file name of frame `frame` of `frames`.
  std::string expand(const TemplateValues& values, int frame, int frames) const;

 private:
  enum class Kind { Text, Scene, Backend, Frame };
  struct Piece {
    Kind kind = Kind::Text;
    std::string text;  // Kind::Text
    int width = 0;     // Kind::Frame: {frame:W}; 0: the digits of the last frame
  };
  std::vector<Piece> pieces_;
};

// {scene} for a scene argument: "" and builtin:default give "default",
// builtin:NAME gives NAME, a file its name without folder and extension.
std::string sceneNameOf(const std::string& scenePath);

}  // namespace facet
