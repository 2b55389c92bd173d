// Filling the pages' templates (view/*.html): a marker such as /*TRIBO_DATA*/ replaced by its
// text, and text made safe to sit inside a <script> element (every "</" written "<\/", so
// neither data nor an embedded script can close the element early; JavaScript reads "<\/" as
// "</"). Shared by the replay, sweep and branch pages.
// Not here: what goes into a page (study/view/view_page.hpp, view_sweep.hpp, view_branch.hpp).
#pragma once

#include <stdexcept>
#include <string>

namespace tribo::study {

// Replaces the first `marker` in `page` by `text`; throws std::logic_error naming the page
// (`what`) and the marker when the template lacks it.
inline void replaceMarker(std::string& page, const std::string& marker, const std::string& text,
                          const std::string& what) {
  const std::size_t at = page.find(marker);
  if (at == std::string::npos) throw std::logic_error(what + " page template lacks " + marker);
  page.replace(at, marker.size(), text);
}

// `text` with every "</" written "<\/".
inline std::string scriptSafe(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out.push_back(text[i]);
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out.push_back('\\');
  }
  return out;
}

}  // namespace tribo::study
