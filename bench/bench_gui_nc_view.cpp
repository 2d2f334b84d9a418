// The NC view's cost of showing a new tape (issue 11), on the 200-unit job's
// linuxcnc tape (bench_job.h's bigJob(200), 20,109 lines):
//   SetPlainText:     what the view did before: QPlainTextEdit::setPlainText;
//   DocumentOnly:     the document alone (one block per line), the part now
//                     made on the maker's thread (ui/nc_document.h);
//   SetDocument:      a made document put in a shown QPlainTextEdit: /plain
//                     as QTextDocument::setPlainText leaves it, /made as
//                     makeNcDocument does (each line's layout object made);
//   NcView/-1:        NcView::setProgram with nothing prepared;
//   NcView/N:         what the station's GUI thread spends: prepared when
//                     the tape arrives, taken N ms later (after the 3-D
//                     view's frame); real time includes waiting for it.
// Offscreen unless a display is set.
#include "bench_job.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/tool_library.h"
#include "model/technology.h"
#include "ui/nc_document.h"
#include "ui/nc_view.h"

#include <QApplication>
#include <QPlainTextDocumentLayout>
#include <QPlainTextEdit>
#include <QTextDocument>

#include <benchmark/benchmark.h>

#include <chrono>
#include <thread>

using namespace taiwa;

namespace {

const PostedProgram& tape()
{
    static const PostedProgram p = [] {
        const auto library = defaultToolLibrary();
        const Plan plan = planJob(bench::bigJob(200), TechnologyTable::builtIn(), library);
        return postProcess(plan.steps, plan.tools, postOptions(plan, "linuxcnc"));
    }();
    return p;
}

void BM_ToQString(benchmark::State& state)
{
    for (auto _ : state) benchmark::DoNotOptimize(QString::fromStdString(tape().nc));
    state.counters["lines"] = static_cast<double>(tape().lines.size());
}

void BM_DocumentOnly(benchmark::State& state)
{
    const QString nc = QString::fromStdString(tape().nc);
    for (auto _ : state) {
        QTextDocument doc;
        doc.setDocumentLayout(new QPlainTextDocumentLayout(&doc));
        doc.setPlainText(nc);
        benchmark::DoNotOptimize(doc.blockCount());
    }
}

void BM_SetDocument(benchmark::State& state, bool made)
{
    const QString nc = QString::fromStdString(tape().nc);
    QPlainTextEdit edit;
    edit.setLineWrapMode(QPlainTextEdit::NoWrap);
    edit.resize(700, 500);
    edit.show();
    QCoreApplication::processEvents();
    QTextDocument* old = nullptr;
    for (auto _ : state) {
        state.PauseTiming();
        QTextDocument* doc = nullptr;
        if (made) {
            doc = ui::makeNcDocument(nc, edit.font()).release();
        } else {
            doc = new QTextDocument;
            doc->setUndoRedoEnabled(false);
            doc->setDocumentLayout(new QPlainTextDocumentLayout(doc));
            doc->setPlainText(nc);
        }
        state.ResumeTiming();
        edit.setDocument(doc);
        QCoreApplication::processEvents();
        state.PauseTiming();
        delete old;
        old = doc;
        state.ResumeTiming();
    }
}

void BM_SetPlainText(benchmark::State& state)
{
    const QString nc = QString::fromStdString(tape().nc);
    QPlainTextEdit edit;
    edit.setReadOnly(true);
    edit.setLineWrapMode(QPlainTextEdit::NoWrap);
    edit.resize(700, 500);
    edit.show();
    int i = 0;
    for (auto _ : state) {
        edit.setPlainText((i++ % 2) ? nc : nc + "\n");
        QCoreApplication::processEvents();
    }
}

// NcView::setProgram; with an argument N, what the station's GUI thread
// spends: the text prepared when the tape arrives, taken N ms later (after
// the 3-D view's frame).
void BM_NcView(benchmark::State& state)
{
    const QString nc = QString::fromStdString(tape().nc);
    ui::NcView view;
    view.resize(700, 500);
    view.show();
    const bool prepared = state.range(0) >= 0;
    int i = 0;
    for (auto _ : state) {
        const QString text = (i++ % 2) ? nc : nc + "\n";
        if (prepared) {
            state.PauseTiming();
            view.prepareProgram(text);
            std::this_thread::sleep_for(std::chrono::milliseconds(state.range(0)));
            state.ResumeTiming();
        }
        view.setProgram(text, tape().lines);
        QCoreApplication::processEvents();
    }
    state.counters["prepared"] = view.preparedShown();
}

}  // namespace

BENCHMARK(BM_ToQString)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SetPlainText)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DocumentOnly)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SetDocument, plain, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SetDocument, made, true)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NcView)->Arg(-1)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
