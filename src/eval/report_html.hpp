// The report's HTML layout (internal): sections (section.hpp) as HTML, and the page around
// them. Layout only: every number and every file name comes in the sections.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ssfx/eval/section.hpp"

namespace ssfx::eval::html {

std::string escape(std::string_view s);
//! Escaped prose with `code` spans and [label](path) links.
std::string inlineText(std::string_view s);
std::string table(const Table& t);
std::string section(const Section& s);
//! The whole page: head with the report's CSS, `intro` (title and note), the sections, a
//! footer paragraph, the viewers' script.
std::string page(const Section& intro, const std::vector<Section>& sections, const std::string& footer);
//! A method doc as a page of its own (methods/ID.html).
std::string docPage(std::string_view id, std::string_view text);

//! A viewer's pixel script (Viewer::pixels): ssfxPixels[id] = {label: "data:image/png;base64,..."}
//! for each (label, PNG file bytes).
std::string pixelScript(const std::string& id, const std::vector<std::pair<std::string, std::string>>& pngs);
//! RFC 4648 base64 (with padding).
std::string base64(std::string_view bytes);

}  // namespace ssfx::eval::html
