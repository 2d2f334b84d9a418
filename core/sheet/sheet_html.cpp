// The machining instruction sheet as a self-contained HTML document.
#include "sheet/sheet.h"

#include "sheet/sheet_content.h"
#include "sheet/tool_drawing.h"

namespace taiwa {

namespace {

// RFC 4648 base64, for the pictures inlined as data: URLs.
std::string base64(const std::string& bytes)
{
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string escape(const std::string& s)
{
    std::string out;
    for (const char c : s) {
        switch (c) {
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '&': out += "&amp;"; break;
        case '"': out += "&quot;"; break;
        default:
            // Control characters (NUL, ESC…) have no place in a document: shown as �.
            if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7f) out += "&#xFFFD;";
            else out += c;
        }
    }
    return out;
}

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 9pt; color: #000; }
h1 { font-size: 14pt; margin: 0 0 4pt 0; }
h2 { font-size: 11pt; margin: 10pt 0 3pt 0; }
table { border-collapse: collapse; }
th, td { border: 1px solid #555; padding: 2pt 4pt; }
th { background: #ddd; text-align: left; }
.fault { color: #c00000; }
.pictures { display: flex; flex-wrap: wrap; gap: 6pt; }
.pictures figure { margin: 0; width: 240px; }
.pictures img { width: 240px; height: 180px; border: 1px solid #555; }
.pictures figcaption, .drawings figcaption { font-size: 8pt; }
.setup { margin: 0; }
.setup img { width: 320px; height: 240px; border: 1px solid #555; }
.drawings { display: flex; flex-wrap: wrap; gap: 6pt; }
.drawings figure { margin: 0; }
svg.tool { border: 1px solid #555; background: #fff; }
td.n { text-align: right; }
table.head td { border: none; padding: 1pt 8pt 1pt 0; }
)css";

std::string table(const sheet::Table& t)
{
    std::string h = "<table><tr>";
    for (const auto& c : t.headers) h += "<th>" + escape(c) + "</th>";
    h += "</tr>\n";
    for (const auto& row : t.rows) {
        h += "<tr>";
        for (std::size_t i = 0; i < row.size(); ++i) h += (t.numeric[i] ? "<td class=n>" : "<td>") + escape(row[i]) + "</td>";
        h += "</tr>\n";
    }
    return h + "</table>\n";
}

// A picture inlined as a PNG data: URL, with its caption under it.
std::string image(const sheet::Content::Picture& p)
{
    return "<img alt=\"" + escape(p.caption) + "\" src=\"data:image/png;base64," + base64(p.png) + "\"><figcaption>" +
           escape(p.caption) + "</figcaption>";
}

}  // namespace

std::string sheetHtml(const Plan& plan, const SheetOptions& options)
{
    const sheet::Content c = sheet::content(plan, options);
    std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escape(c.title) + " – " +
                    escape(plan.job.name) + "</title><style>" + kStyle + "</style></head><body>\n<h1>" + escape(c.title) +
                    "</h1>\n<table class=\"head\">";
    for (std::size_t i = 0; i < c.fields.size(); ++i) {
        if (i % 3 == 0) h += (i ? "</tr>" : "") + std::string("<tr>");
        h += "<td><b>" + escape(c.fields[i].first) + "</b></td><td>" + escape(c.fields[i].second) + "</td>";
    }
    h += "</tr></table>\n<p>" + escape(c.setup) + "</p>\n";
    if (!c.clamping.empty()) h += "<p>" + escape(c.clamping) + "</p>\n";
    if (!c.toolsOrigin.empty()) h += "<p>" + escape(c.toolsOrigin) + "</p>\n";
    if (c.setupPicture) h += "<figure class=\"setup\">" + image(*c.setupPicture) + "</figure>\n";
    if (!c.faults.empty()) {
        h += "<h2 class=\"fault\">Verification: written with faults (--force)</h2>\n<ul class=\"fault\">";
        for (const auto& f : c.faults) h += "<li>" + escape(f) + "</li>";
        h += "</ul>\n";
    }
    if (!c.workCentre.rows.empty()) h += "<h2>Work centre</h2>\n" + table(c.workCentre);
    if (!c.allowances.rows.empty())
        h += "<h2>Grinding allowances</h2>\n" + table(c.allowances) + "<h2>Turned profile as cut</h2>\n" + table(c.turned);
    h += "<h2>Process steps</h2>\n" + table(c.steps);
    for (const auto& p : c.paths)
        h += "<h2>" + escape(p.heading) + "</h2>\n" + table(p.table) + (p.note.empty() ? "" : "<p>" + escape(p.note) + "</p>\n");
    if (!c.pictures.empty() || !c.picturesNote.empty()) {
        h += "<h2>The steps in pictures</h2>\n";
        if (!c.picturesNote.empty()) h += "<p>" + escape(c.picturesNote) + "</p>\n";
        h += "<div class=\"pictures\">";
        for (const auto& p : c.pictures) h += "<figure>" + image(p) + "</figure>";
        h += "</div>\n";
    }
    h += "<h2>Tools</h2>\n" + table(c.tools);
    if (!c.toolDrawings.empty()) {
        h += "<div class=\"drawings\">";
        for (const auto& d : c.toolDrawings)
            h += "<figure>" + sheet::toolDrawingSvg(d.drawing) + "<figcaption>" + escape(d.caption) + "</figcaption></figure>";
        h += "</div>\n";
    }
    if (!c.latheTools.rows.empty()) h += "<h2>Turret</h2>\n" + table(c.latheTools);
    if (!c.notes.empty()) {
        h += "<h2>Notes</h2>\n<ul>";
        for (const auto& n : c.notes) h += "<li>" + escape(n) + "</li>";
        h += "</ul>\n";
    }
    return h + "<p><b>Total:</b> " + escape(c.total) + ".</p>\n</body></html>\n";
}

}  // namespace taiwa
