// The machining instruction sheet as a self-contained HTML document.
#include "sheet/sheet.h"

#include "tools/cutting.h"

#include <fmt/format.h>

#include <cmath>

namespace taiwa {

namespace {

std::string escape(const std::string& s)
{
    std::string out;
    for (const char c : s) {
        switch (c) {
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '&': out += "&amp;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 9pt; color: #000; }
h1 { font-size: 14pt; margin: 0 0 4pt 0; }
h2 { font-size: 11pt; margin: 10pt 0 3pt 0; }
table { border-collapse: collapse; width: 100%; }
th, td { border: 1px solid #555; padding: 2pt 4pt; }
th { background: #ddd; text-align: left; }
td.n { text-align: right; }
table.head td { border: none; padding: 1pt 8pt 1pt 0; }
)css";

}  // namespace

std::string sheetHtml(const Plan& plan, const SheetOptions& o)
{
    const LengthUnit u = o.units;
    const char* us = unitSymbol(u);
    const auto len = [&](double mm) { return fmt::format("{:.{}f}", fromMm(mm, u), u == LengthUnit::Inch ? 4 : 3); };
    const auto feed = [&](double mmPerMin) { return fmt::format("{:.{}f}", fromMm(mmPerMin, u), u == LengthUnit::Inch ? 1 : 0); };
    const Job& job = plan.mmJob;
    std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Machining instruction sheet – " +
                    escape(plan.job.name) + "</title><style>" + kStyle + "</style></head><body>\n";
    h += "<h1>Machining instruction sheet</h1>\n<table class=\"head\">";
    h += fmt::format("<tr><td><b>Job</b></td><td>{}</td><td><b>File</b></td><td>{}</td><td><b>Dialect</b></td><td>{}</td></tr>",
                     escape(plan.job.name), escape(o.jobFile), escape(o.dialect));
    h += fmt::format("<tr><td><b>Material</b></td><td>{}</td><td><b>Machine</b></td><td>{}</td><td><b>Date</b></td><td>{}</td></tr>",
                     escape(job.material), escape(job.machine), escape(o.date));
    h += fmt::format("<tr><td><b>Stock</b></td><td>{} × {} × {} {}</td><td><b>Work offset</b></td><td>{}</td>"
                     "<td><b>Setup</b></td><td>X0 Y0 at the stock's front-left corner{}, Z0 on its top face</td></tr>",
                     len(job.stock.width), len(job.stock.length), len(job.stock.height), us, escape(job.workOffset),
                     job.stock.x == 0 && job.stock.y == 0 ? "" : fmt::format(" (stock corner at X{} Y{})", len(job.stock.x), len(job.stock.y)));
    h += fmt::format("<tr><td><b>Steps</b></td><td>{}</td><td><b>Tool changes</b></td><td>{}</td><td><b>Total time</b></td><td>{:.1f} min</td></tr>",
                     plan.steps.size(), plan.toolChanges, plan.totalMinutes);
    h += "</table>\n<h2>Process steps</h2>\n<table cellspacing=\"0\" cellpadding=\"3\" border=\"1\"><tr><th>No.</th><th>Unit</th><th>Module</th><th>Step</th><th>T</th><th>H</th><th>Tool</th>"
         "<th>S rpm</th><th>F " + std::string(us) + "/min</th><th>Start " + us + "</th><th>Depth " + us +
         "</th><th>Wall left</th><th>Floor left</th><th>Path " + us + "</th><th>Min</th></tr>\n";
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const Step& s = plan.steps[i];
        const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr;
        const auto sf = t ? speedsFeeds(*t, job.material) : std::nullopt;
        const PathLength pl = s.path ? pathLength(*s.path) : PathLength{};
        h += fmt::format("<tr><td class=n>{}</td><td class=n>{}</td><td>{}</td><td>{}</td><td class=n>{}</td><td class=n>{}</td><td>{}</td>"
                         "<td class=n>{}</td><td class=n>{}</td><td class=n>{}</td><td class=n>{}</td><td class=n>{}</td>"
                         "<td class=n>{}</td><td class=n>{}</td><td class=n>{}</td></tr>\n",
                         i + 1, s.unit + 1, s.module, escape(s.label()), t ? std::to_string(t->id) : "–",
                         t ? std::to_string(t->id) : "–", t ? escape(t->name) : "–", sf ? fmt::format("{:.0f}", sf->rpm) : "–",
                         sf ? feed(sf->feed) : "–", len(s.startDepth), len(s.cutDepth), len(s.wallAllowance),
                         len(s.floorAllowance), s.path ? len(pl.feed + pl.rapid) : "–",
                         s.minutes ? fmt::format("{:.2f}", *s.minutes) : "–");
    }
    h += "</table>\n<h2>Tools</h2>\n<table cellspacing=\"0\" cellpadding=\"3\" border=\"1\"><tr><th>T</th><th>Tool</th><th>Type</th><th>Diameter " + std::string(us) +
         "</th><th>Stick-out " + us + "</th><th>Holder</th><th>Life min</th><th>Used min</th><th>Left min</th></tr>\n";
    for (const auto& t : plan.tools)
        h += fmt::format("<tr><td class=n>{}</td><td>{}</td><td>{}</td><td class=n>{}</td><td class=n>{}</td><td>{}</td>"
                         "<td class=n>{:.0f}</td><td class=n>{:.1f}</td><td class=n>{:.1f}</td></tr>\n",
                         t.id, escape(t.name), toString(t.type), len(t.diameter), len(t.stickout), escape(t.holder),
                         t.lifeMinutes, t.usedMinutes, t.remainingLife());
    h += "</table>\n";
    if (!plan.notes.empty()) {
        h += "<h2>Notes</h2>\n<ul>";
        for (const auto& n : plan.notes) h += "<li>" + escape(n) + "</li>";
        h += "</ul>\n";
    }
    h += fmt::format("<p><b>Total:</b> {:.1f} min including {} tool changes.</p>\n</body></html>\n", plan.totalMinutes,
                     plan.toolChanges);
    return h;
}

}  // namespace taiwa
