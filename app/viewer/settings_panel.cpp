#include "viewer/settings_panel.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

#include <glm/geometric.hpp>
#include <imgui.h>

#include "settings/settings_fields.h"
#include "viewer/camera_controls.h"

namespace facet::viewer {
namespace {

// A bounded number whose range is at most this wide gets a slider; wider
// ranges (near, far, intensity, map size) and unbounded ones get a drag box
// whose speed follows the value, since a slider over [1e-6, 1e9] cannot
// land on anything.
constexpr double kSliderSpan = 100.0;
constexpr const char* kFloatFormat = "%.4g";  // ImGui also rounds edits to this: 4 significant digits
constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;  // ctrl+click typing stays in range too

bool isBounded(const FieldInfo& info) { return info.min < info.max; }

bool isColor(const FieldInfo& info) { return info.kind == FieldKind::Color; }

// Where an optional value starts when its override is switched on: the middle
// of its range, on a log scale for wide ranges (shininess in [1, 4096]: 64).
float startValue(const FieldInfo& info) {
  if (!isBounded(info)) return 1.0f;
  if (info.min > 0.0 && info.max / info.min > kSliderSpan) return static_cast<float>(std::sqrt(info.min * info.max));
  return static_cast<float>(0.5 * (info.min + info.max));
}

bool editFloat(const char* label, float& value, const FieldInfo& info, const char* format = kFloatFormat) {
  const float lo = static_cast<float>(info.min), hi = static_cast<float>(info.max);
  if (isBounded(info) && info.max - info.min <= kSliderSpan) return ImGui::SliderFloat(label, &value, lo, hi, format, kClamp);
  const float speed = std::max(std::abs(value) * 0.005f, 1e-4f);
  return ImGui::DragFloat(label, &value, speed, lo, hi, format, kClamp);  // lo == hi == 0: unbounded
}

// What the panel calls a field: its label, then its unit when it has one,
// "half-angle of view (degrees)". The ID after "##" is the key, so two
// fields with the same label never share one.
std::string shownLabel(const FieldInfo& info) {
  std::string text(info.label);
  if (!info.unit.empty()) text.append(" (").append(info.unit).append(")");
  return text;
}

// The width of the widest label the panel will draw, lists' items included.
class LabelMeasure {
 public:
  float widest() const { return widest_; }

  template <class T>
  void field(const FieldInfo& info, const T&) {
    measure(info);
  }
  template <class Enum, std::size_t N>
  void choice(const FieldInfo& info, const Enum&, const std::array<std::string_view, N>&) {
    measure(info);
  }
  template <class Fn>
  void group(std::string_view, Fn&& fn) {
    fn();
  }
  template <class T>
  void list(const ListInfo&, std::vector<T>&) {
    T item;
    visitItem(*this, item);
  }

 private:
  void measure(const FieldInfo& info) { widest_ = std::max(widest_, ImGui::CalcTextSize(shownLabel(info).c_str()).x); }

  float widest_ = 0.0f;
};

// What a list item's header says after its number: a light's kind.
std::string itemTitle(const Light& light) { return ": " + std::string(kLightKindNames[static_cast<std::size_t>(light.kind)]); }
std::string itemTitle(const Emitter&) { return ""; }

class PanelVisitor {
 public:
  explicit PanelVisitor(float worldScale) : worldScale_(worldScale) {}

  // The dotted key of the field that changed this frame; empty when none did.
  const std::string& changedKey() const { return changedKey_; }

  void field(const FieldInfo& info, float& value) {
    if (editFloat(label(info), value, info)) changed(info.key);
    tooltip(info);
  }

  void field(const FieldInfo& info, int& value) {
    const int lo = static_cast<int>(info.min), hi = static_cast<int>(info.max);
    const bool edited = isBounded(info) && info.max - info.min <= kSliderSpan
                            ? ImGui::SliderInt(label(info), &value, lo, hi, "%d", kClamp)
                            : ImGui::DragInt(label(info), &value, std::max(1.0f, static_cast<float>(info.max - info.min) / 2000.0f), lo, hi,
                                             "%d", kClamp);
    if (edited) changed(info.key);
    tooltip(info);
  }

  void field(const FieldInfo& info, bool& value) {
    if (ImGui::Checkbox(label(info), &value)) changed(info.key);
    tooltip(info);
  }

  void field(const FieldInfo& info, glm::vec3& value) {
    bool edited = false;
    if (isColor(info)) {
      edited = ImGui::ColorEdit3(label(info), &value.x, ImGuiColorEditFlags_Float);
    } else {
      // Positions move in steps that suit the scene's size, directions in hundredths.
      const float speed = 0.005f * std::max(glm::length(value), worldScale_);
      edited = ImGui::DragFloat3(label(info), &value.x, speed, static_cast<float>(info.min), static_cast<float>(info.max), kFloatFormat,
                                 kClamp);
    }
    if (edited) changed(info.key);
    tooltip(info);
  }

  // A checkbox switches the override on; the slider beside it shows
  // "derived" while the glTF-derived value is in use.
  void field(const FieldInfo& info, std::optional<float>& value) {
    bool overridden = value.has_value();
    ImGui::PushID(label(info));
    if (ImGui::Checkbox("##override", &overridden)) {
      value = overridden ? std::optional<float>(startValue(info)) : std::nullopt;
      changed(info.key);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("override the value derived from each glTF material");
    ImGui::PopID();
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemInnerSpacing.x);
    float number = value.value_or(startValue(info));
    ImGui::BeginDisabled(!overridden);
    if (editFloat(label(info), number, info, overridden ? kFloatFormat : "derived")) {
      value = number;
      changed(info.key);
    }
    ImGui::EndDisabled();
    tooltip(info);
  }

  // A file name: edited as text, taken when Enter is pressed.
  void field(const FieldInfo& info, std::string& value) {
    char text[kMaxSettingsPathBytes + 1] = {};
    value.copy(text, std::min(value.size(), kMaxSettingsPathBytes));
    if (ImGui::InputText(label(info), text, sizeof text, ImGuiInputTextFlags_EnterReturnsTrue)) {
      value = text;
      changed(info.key);
    }
    tooltip(info);
  }

  template <class Enum, std::size_t N>
  void choice(const FieldInfo& info, Enum& value, const std::array<std::string_view, N>& names) {
    static_assert(N == static_cast<std::size_t>(Enum::Count), "a names table must name every value");
    const std::string preview(names[static_cast<std::size_t>(value)]);
    if (ImGui::BeginCombo(label(info), preview.c_str())) {
      for (std::size_t i = 0; i < N; ++i) {
        const bool selected = static_cast<std::size_t>(value) == i;
        if (ImGui::Selectable(std::string(names[i]).c_str(), selected) && !selected) {
          value = static_cast<Enum>(i);
          changed(info.key);
        }
        if (selected) ImGui::SetItemDefaultFocus();
      }
      ImGui::EndCombo();
    }
    tooltip(info);
    if constexpr (std::is_same_v<Enum, Source>) {
      if (value == Source::Auto) ImGui::TextDisabled("auto: shown below; an edit switches to manual");
    }
  }

  template <class Fn>
  void group(const GroupInfo& info, Fn&& fn) {
    const std::string outer = prefix_;
    const std::string name(info.key);
    const std::string header = std::string(info.label) + "###" + name;
    if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::PushID(name.c_str());
    ImGui::Indent();
    prefix_ = outer + name + ".";
    fn();
    prefix_ = outer;
    ImGui::Unindent();
    ImGui::PopID();
  }

  // One collapsing header per item (a light, an emitter), then add and remove
  // buttons. A new item copies the last one, which is usually near where it should go.
  template <class T>
  void list(const ListInfo& info, std::vector<T>& list) {
    const std::string outer = prefix_;
    const std::string name(info.key), item(info.item);
    const std::string header = std::string(info.label) + " (" + std::to_string(list.size()) + ")###" + name;
    if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::PushID(name.c_str());
    ImGui::Indent();
    std::optional<std::size_t> removed;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string index = std::to_string(i);
      const std::string title = item + " " + index + itemTitle(list[i]) + "###" + item + index;
      ImGui::PushID(static_cast<int>(i));
      if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        prefix_ = outer + name + "." + index + ".";
        visitItem(*this, list[i]);
        prefix_ = outer;
        if (ImGui::Button(("remove this " + item).c_str())) removed = i;
      }
      ImGui::PopID();
    }
    if (removed) {
      list.erase(list.begin() + static_cast<std::ptrdiff_t>(*removed));
      changedKey_ = outer + name + "." + std::to_string(*removed) + ".remove";
    }
    if (ImGui::Button(("add a " + item).c_str()) && list.size() < info.max) {
      list.push_back(list.empty() ? T{} : list.back());
      changedKey_ = outer + name + "." + std::to_string(list.size() - 1) + ".add";
    }
    ImGui::Unindent();
    ImGui::PopID();
  }

 private:
  const char* label(const FieldInfo& info) {
    label_ = shownLabel(info).append("##").append(info.key);
    return label_.c_str();
  }

  void changed(std::string_view key) { changedKey_ = prefix_ + std::string(key); }

  // The dotted key (what --set and the JSON call it), the unit, the help, the range.
  void tooltip(const FieldInfo& info) const {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::Text("%s%.*s", prefix_.c_str(), static_cast<int>(info.key.size()), info.key.data());
    if (!info.unit.empty()) ImGui::Text("in %.*s", static_cast<int>(info.unit.size()), info.unit.data());
    ImGui::TextUnformatted(info.help.data(), info.help.data() + info.help.size());
    if (isBounded(info)) ImGui::TextDisabled("range %g to %g; ctrl+click to type a value", info.min, info.max);
    ImGui::EndTooltip();
  }

  float worldScale_;
  std::string prefix_;      // "camera.", "lights.0.": the dotted key of the current group
  std::string changedKey_;
  std::string label_;       // storage for the label of the control being drawn
};

}  // namespace

RenderSettings shownSettings(const Scene& scene, const RenderSettings& settings) {
  RenderSettings shown = settings;
  if (settings.camera.source == Source::Auto) {
    shown.camera = resolveCamera(scene, settings);
    shown.camera.source = Source::Auto;
  }
  if (settings.lightSource == Source::Auto) shown.lights = resolveLights(scene, settings);
  return shown;
}

RenderSettings editedSettings(const RenderSettings& settings, const RenderSettings& shown, std::string_view changedKey,
                              const Sphere& sphere) {
  const auto startsWith = [&](std::string_view prefix) { return changedKey.substr(0, prefix.size()) == prefix; };
  RenderSettings edited = shown;

  if (changedKey == "camera.projection") {
    // Auto fits either projection itself; a manual camera keeps its width of view.
    edited.camera = settings.camera;
    if (settings.camera.source == Source::Auto)
      edited.camera.projection = shown.camera.projection;
    else
      toggleProjection(edited.camera, sphere);
  } else if (settings.camera.source == Source::Auto) {
    if (changedKey == "camera.source") {
      // to manual, from the values auto chose: shown.camera as it is
    } else if (startsWith("camera.")) {
      edited.camera.source = Source::Manual;
    } else {
      edited.camera = settings.camera;  // untouched: auto, with its own values
    }
  }

  if (settings.lightSource == Source::Auto) {
    if (changedKey == "lightSource") {
      // to manual, from the lights auto chose
    } else if (startsWith("lights.")) {
      edited.lightSource = Source::Manual;
    } else {
      edited.lights = settings.lights;
    }
  }
  return edited;
}

bool drawSettingsPanel(RenderSettings& settings, const Scene& scene, const Sphere& sphere) {
  RenderSettings shown = shownSettings(scene, settings);
  PanelVisitor visitor(sphere.radius);
  // Room on the right for the widest label, but never more than 60% of the
  // panel: a longer label is cut at the edge (its tooltip has it all).
  LabelMeasure measure;
  visitSettings(measure, shown);
  const float labelRoom = measure.widest() + ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::PushItemWidth(-std::min(labelRoom, 0.6f * ImGui::GetContentRegionAvail().x));
  visitSettings(visitor, shown);
  ImGui::PopItemWidth();
  if (visitor.changedKey().empty()) return false;
  settings = editedSettings(settings, shown, visitor.changedKey(), sphere);
  return true;
}

}  // namespace facet::viewer
