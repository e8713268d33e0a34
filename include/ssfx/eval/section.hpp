// A report section as data: what each experiment returns (tables, figures, plots, image
// viewers, prose), laid out by the HTML report (report.hpp) and written as Markdown into
// data/*.md by markdown() below. Neither format is parsed back.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ssfx::eval {

//! A table of formatted cells; header[0] names the row-label column. `best` marks cells to
//! set in bold (empty, or one flag per cell).
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::vector<std::vector<bool>> best;

    bool empty() const { return rows.empty(); }
    void addRow(std::vector<std::string> cells) { rows.push_back(std::move(cells)); }
};

//! Rows x columns of numbers with `decimals` decimals ("-" for NaN, "inf"), the best of each
//! row (the highest, or the lowest) marked.
Table numericTable(const std::string& corner, const std::vector<std::string>& rowNames,
                   const std::vector<std::string>& columns, const std::vector<std::vector<double>>& values,
                   int decimals, bool higherIsBetter);

//! An image of the section: `path` relative to the report's folder.
struct Figure {
    std::string path;
    std::string caption;
    enum class Kind { Image, Crop, Plot, Animation } kind = Kind::Image;
    int width = 0, height = 0;  //!< plots: their size in pixels
};

//! The interactive comparison of one image's outputs: `sources` are (label, path) pairs.
struct Viewer {
    std::string id;
    int width = 0, height = 0;
    std::vector<std::pair<std::string, std::string>> sources;
    std::vector<std::string> initial;  //!< labels picked at first
    std::string reference = "truth";   //!< the label the difference mode and readout compare with
    //! A script defining ssfxPixels[id] = {label: PNG data URL} (writePixelScript), for the
    //! difference mode and the per-pixel readout; empty: the viewer has neither.
    std::string pixels;
};

//! A term with its description and a link (the method list).
struct Definition {
    std::string term, description, citation, link;
};

//! One subsection: heading, a paragraph, then whatever it has, in this order. Text may mark
//! `code` with backticks; everything is escaped when laid out.
struct Block {
    std::string heading;
    std::string text;
    std::vector<Definition> definitions;
    Table table;
    std::string after;  //!< a paragraph after the table
    std::vector<Figure> figures;
    std::vector<Viewer> viewers;
};

struct Section {
    std::string title;  //!< the h2 heading
    std::string note;   //!< the paragraph under it
    std::vector<Block> blocks;
};

//! The Markdown of a table: a pipe table, the first column left-aligned, the others right.
std::string markdown(const Table& table);
//! "### heading", the text, the table and the paragraph after it, per block, with blank lines
//! between (figures and viewers are the HTML's).
std::string markdown(const Section& section);

//! Prefixes every figure's and viewer's path with `dir` (a section written into a subfolder).
void prefixPaths(Section& section, const std::string& dir);

}  // namespace ssfx::eval
