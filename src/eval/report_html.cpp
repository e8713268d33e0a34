// The report's HTML layout (see report_html.hpp).
#include "src/eval/report_html.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "src/eval/report_assets.hpp"

namespace ssfx::eval::html {

std::string escape(std::string_view s) {
    std::string o;
    for (char c : s) {
        switch (c) {
            case '&': o += "&amp;"; break;
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '"': o += "&quot;"; break;
            default: o += c;
        }
    }
    return o;
}

std::string inlineText(std::string_view s) {
    std::string o;
    bool code = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '`') {
            o += code ? "</code>" : "<code>";
            code = !code;
            continue;
        }
        if (c == '[' && !code) {  // [label](path)
            const std::size_t close = s.find("](", i),
                              end = close == std::string_view::npos ? close : s.find(')', close);
            if (end != std::string_view::npos) {
                o += fmt::format("<a href=\"{}\">{}</a>", escape(s.substr(close + 2, end - close - 2)),
                                 escape(s.substr(i + 1, close - i - 1)));
                i = end;
                continue;
            }
        }
        o += escape(std::string_view(&c, 1));
    }
    return o + (code ? "</code>" : "");
}

std::string table(const Table& t) {
    std::string s = "<table><tr>";
    for (const auto& h : t.header) s += "<th>" + inlineText(h) + "</th>";
    s += "</tr>\n";
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        s += "<tr>";
        for (std::size_t c = 0; c < t.rows[r].size(); ++c) {
            const bool best = r < t.best.size() && c < t.best[r].size() && t.best[r][c];
            s += fmt::format("<td{}>{}</td>", best ? " class=\"best\"" : "", inlineText(t.rows[r][c]));
        }
        s += "</tr>\n";
    }
    return s + "</table>\n";
}

namespace {

std::string figure(const Figure& f) {
    const char* cls = f.kind == Figure::Kind::Crop    ? " class=\"crop\""
                      : f.kind == Figure::Kind::Image ? " class=\"aoimg\""
                                                      : "";
    return fmt::format("<figure><img{} src=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>\n", cls,
                       escape(f.path), escape(f.caption), inlineText(f.caption));
}

std::string plot(const Figure& f) {
    return fmt::format("<img class=\"plot\" width=\"{}\" height=\"{}\" src=\"{}\" alt=\"{}\">\n", f.width, f.height,
                       escape(f.path), escape(f.caption));
}

// Plots stand alone; the other figures of a run side by side in one row.
std::string figures(const std::vector<Figure>& list) {
    std::string s;
    bool open = false;
    for (const Figure& f : list) {
        if (f.kind == Figure::Kind::Plot) {
            if (open) s += "</div>\n", open = false;
            s += plot(f);
        } else {
            if (!open) s += "<div class=\"anims\">\n", open = true;
            s += figure(f);
        }
    }
    return open ? s + "</div>\n" : s;
}

std::string viewer(const Viewer& v) {
    nlohmann::ordered_json src = nlohmann::ordered_json::object();
    for (const auto& [label, url] : v.sources) src[label] = url;
    const nlohmann::json init = v.initial;
    const bool exact = !v.pixels.empty();
    std::string s = fmt::format(
        "<section class=\"viewer\" id=\"viewer-{0}\" data-viewer=\"{0}\" data-width=\"{1}\" data-height=\"{2}\" "
        "data-pane-width=\"{3}\" data-pane-height=\"{4}\" data-sources=\"{5}\" data-initial=\"{6}\" "
        "data-reference=\"{7}\"{8}>\n<div class=\"controls\"><span>methods</span>",
        escape(v.id), v.width, v.height, 400, 400, escape(src.dump()), escape(init.dump()), escape(v.reference),
        exact ? fmt::format(" data-pixels=\"{}\"", escape(v.pixels)) : "");
    for (const auto& [label, url] : v.sources)
        s += fmt::format("<button data-method=\"{0}\">{0}</button>", escape(label));
    s += "<span>mode</span><button data-mode=\"side\">side by side</button><button data-mode=\"flip\">flip</button>"
         "<button data-action=\"flip\" title=\"next picked method (key f)\">next</button>"
         "<button data-action=\"auto\">auto-flip</button>"
         "<button data-mode=\"wipe\" title=\"the first picked method left of the slider, the second right\">wipe"
         "</button><input type=\"range\" min=\"0\" max=\"1000\" data-action=\"wipe\" aria-label=\"wipe position\">";
    if (exact) {
        s += fmt::format(
            "<button data-mode=\"diff\" title=\"|method - {0}|, magnified\">difference</button>"
            "<span>gain</span>",
            escape(v.reference));
        for (int g : {1, 4, 16, 64}) s += fmt::format("<button data-gain=\"{0}\">{0}x</button>", g);
    }
    s += "<span>zoom</span>";
    for (int z : {1, 2, 4, 8, 16}) s += fmt::format("<button data-zoom=\"{0}\">{0}x</button>", z);
    s += "</div>\n";
    if (exact)
        s += fmt::format(
            "<div class=\"legend\" hidden><span>|method - {}|, max over R, G, B, times the gain:</span><span>0</span>"
            "<span class=\"ramp\"></span><span class=\"hi\"></span></div>\n",
            escape(v.reference));
    s += "<div class=\"panes\"></div>\n";
    if (exact) s += "<div class=\"readout\" aria-live=\"polite\">(move the cursor over an image)</div>\n";
    s += "</section>\n";
    return s;
}

std::string block(const Block& b) {
    std::string s;
    if (!b.heading.empty()) s += "<h3>" + inlineText(b.heading) + "</h3>\n";
    if (!b.text.empty()) s += "<p class=\"note\">" + inlineText(b.text) + "</p>\n";
    if (!b.definitions.empty()) {
        s += "<dl class=\"methods\">\n";
        for (const Definition& d : b.definitions)
            s += fmt::format("<dt id=\"m-{0}\">{0}</dt><dd>{1} <em>{2}</em> (<a href=\"{3}\">doc</a>)</dd>\n",
                             escape(d.term), escape(d.description), escape(d.citation), escape(d.link));
        s += "</dl>\n";
    }
    if (!b.table.header.empty()) s += table(b.table);
    if (!b.after.empty()) s += "<p class=\"note\">" + inlineText(b.after) + "</p>\n";
    s += figures(b.figures);
    for (const Viewer& v : b.viewers) s += viewer(v);
    return s;
}

}  // namespace

std::string section(const Section& s) {
    std::string h;
    if (!s.title.empty()) h += "<h2>" + inlineText(s.title) + "</h2>\n";
    if (!s.note.empty()) h += "<p class=\"note\">" + inlineText(s.note) + "</p>\n";
    for (const Block& b : s.blocks) h += block(b);
    return h;
}

std::string page(const Section& intro, const std::vector<Section>& sections, const std::string& footer) {
    std::string h = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
        "<title>ssfx evaluation report</title><link rel=\"icon\" href=\"data:,\"><style>{}</style></head><body>\n",
        detail::kReportCss);
    h += "<h1>" + inlineText(intro.title) + "</h1>\n<p class=\"note\">" + inlineText(intro.note) + "</p>\n";
    for (const Section& s : sections) h += section(s);
    h += "<p class=\"note\">" + inlineText(footer) + "</p>\n";
    h += "<script>" + std::string(detail::kReportJs) + "</script>\n</body></html>\n";
    return h;
}

std::string docPage(std::string_view id, std::string_view text) {
    return fmt::format(
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>ssfx: {0}</title>"
        "<style>{1}</style></head><body><p><a href=\"../index.html\">back to the report</a></p>"
        "<pre class=\"doc\">{2}</pre></body></html>\n",
        escape(id), detail::kReportCss, escape(text));
}

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? std::uint8_t(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

std::string pixelScript(const std::string& id, const std::vector<std::pair<std::string, std::string>>& pngs) {
    nlohmann::ordered_json urls = nlohmann::ordered_json::object();
    for (const auto& [label, bytes] : pngs) urls[label] = "data:image/png;base64," + base64(bytes);
    return fmt::format("window.ssfxPixels = window.ssfxPixels || {{}};\nwindow.ssfxPixels[{}] = {};\n",
                       nlohmann::json(id).dump(), urls.dump());
}

}  // namespace ssfx::eval::html
