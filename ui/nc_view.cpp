// The NC view and its line <-> (step, move) mapping.
#include "ui/nc_view.h"

#include "ui/nc_document.h"
#include "ui/nc_highlighter.h"

#include <QEvent>
#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalBlocker>
#include <QTextBlock>
#include <QTextDocument>
#include <QVBoxLayout>

#include <utility>

namespace taiwa::ui {

NcView::NcView(QWidget* parent)
    : QWidget(parent), dialect_(new QComboBox(this)), summary_(new QLabel(this)), text_(new QPlainTextEdit(this)),
      maker_(std::make_unique<NcDocumentMaker>())
{
    dialect_->setObjectName("nc.dialect");
    for (const std::string& d : dialectNames()) dialect_->addItem(QString::fromStdString(d));
    text_->setObjectName("nc");
    text_->setReadOnly(true);
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    text_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    text_->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    highlighter_ = new NcHighlighter(text_);

    // The label and the dialect over the program, the block count under it:
    // each whole in every language at 1280 px (test_gui_form_fit), where the
    // step list beside takes what the heading leaves.
    auto* top = new QHBoxLayout;
    label_ = new QLabel(this);
    label_->setObjectName("nc.label");
    summary_->setObjectName("nc.blocks");
    summary_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    label_->setBuddy(dialect_);
    top->addWidget(label_);
    nameParts();
    top->addWidget(dialect_);
    top->addStretch(1);
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    box->addLayout(top);
    box->addWidget(text_, 1);
    box->addWidget(summary_);

    connect(dialect_, &QComboBox::currentTextChanged, this, &NcView::useRulesOf);
    connect(dialect_, &QComboBox::currentTextChanged, this, &NcView::dialectChanged);
    useRulesOf(dialect_->currentText());
    connect(text_, &QPlainTextEdit::cursorPositionChanged, this, &NcView::onCursorMoved);
}

NcView::~NcView()
{
    text_->setDocument(nullptr);  // the view's own again, before the one shown is freed
    maker_->dispose(std::move(document_));
}

QString lastChosenDialect()
{
    const QString d = QSettings().value("nc/dialect", "linuxcnc").toString();
    return isDialect(d.toStdString()) ? d : QStringLiteral("linuxcnc");
}

void rememberDialect(const QString& dialect) { QSettings().setValue("nc/dialect", dialect); }

QString NcView::dialect() const { return dialect_->currentText(); }

void NcView::setDialect(const QString& dialect)
{
    const QSignalBlocker quiet(dialect_);
    dialect_->setCurrentText(dialect);
    useRulesOf(dialect_->currentText());
}

void NcView::nameParts()
{
    label_->setText(tr("&NC dialect:"));
    if (!lines_.empty()) summary_->setText(tr("%n block(s)", "", static_cast<int>(lines_.size())));
}

void NcView::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() == QEvent::LanguageChange) nameParts();
}

void NcView::useRulesOf(const QString& dialect)
{
    const post::Dialect* d = post::findDialect(dialect.toStdString());
    highlighter_->setRules(d ? d->highlighting : post::Highlighting{});
}

void NcView::setProgram(const QString& nc, const std::vector<BlockSource>& lines)
{
    lines_ = lines;
    showText(nc);
    summary_->setText(tr("%n block(s)", "", static_cast<int>(lines_.size())));
}

void NcView::setStale(bool stale)
{
    text_->setStyleSheet(stale ? QStringLiteral("QPlainTextEdit { color: #9a9a9a; }") : QString());
}

void NcView::setMessage(const QString& text)
{
    lines_.clear();
    showText(text);
    summary_->clear();
}

void NcView::prepareProgram(const QString& nc) { maker_->prepare(nc, text_->font()); }

bool NcView::isPrepared(const QString& nc) const { return maker_->ready(nc); }

int NcView::preparedShown() const { return maker_->taken(); }

void NcView::showText(const QString& text)
{
    // The document swapped, not its text replaced: building a document of
    // 20,000 lines is what took the time, and it is done on the maker's
    // thread when prepared; the old one is freed there too.
    auto doc = maker_->take(text, text_->font());
    selecting_ = true;
    text_->setDocument(doc.get());
    highlighter_->watch(doc.get());
    onCursorMoved();  // the band on the first line, as a new text puts it
    selecting_ = false;
    maker_->dispose(std::exchange(document_, std::move(doc)));
}

bool NcView::selectMove(int step, int move)
{
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        if (lines_[i].step != step || lines_[i].move != move) continue;
        const QTextBlock block = text_->document()->findBlockByNumber(static_cast<int>(i));
        QTextCursor c(block);
        c.select(QTextCursor::LineUnderCursor);
        selecting_ = true;
        text_->setTextCursor(c);
        text_->centerCursor();
        selecting_ = false;
        return true;
    }
    return false;
}

void NcView::showStep(int step)
{
    if (step < 0) return;
    // The step's heading ("(STEP 2: UNIT 1 …)"), else its first line: a line
    // written as the step begins may still close the step before (a G80).
    const QString heading = QStringLiteral("STEP %1:").arg(step + 1);
    int first = -1, headed = -1;
    for (std::size_t i = 0; i < lines_.size() && headed < 0; ++i) {
        if (lines_[i].step != step) {
            if (first >= 0) break;
            continue;
        }
        if (first < 0) first = static_cast<int>(i);
        if (text_->document()->findBlockByNumber(static_cast<int>(i)).text().contains(heading)) headed = static_cast<int>(i);
    }
    if (first < 0) return;
    selecting_ = true;
    text_->setTextCursor(QTextCursor(text_->document()->findBlockByNumber(headed >= 0 ? headed : first)));
    text_->centerCursor();
    selecting_ = false;
}

BlockSource NcView::currentSource() const
{
    const int line = text_->textCursor().blockNumber();
    return line >= 0 && line < static_cast<int>(lines_.size()) ? lines_[static_cast<std::size_t>(line)] : BlockSource{};
}

void NcView::onCursorMoved()
{
    // The block the cursor is on, as a band across the view, whoever moved it.
    QTextEdit::ExtraSelection band;
    band.format.setBackground(QColor(255, 243, 176));
    band.format.setProperty(QTextFormat::FullWidthSelection, true);
    band.cursor = text_->textCursor();
    band.cursor.clearSelection();
    text_->setExtraSelections({band});
    highlightedLine_ = band.cursor.blockNumber();
    if (selecting_) return;
    const BlockSource s = currentSource();
    if (s.step >= 0) emit moveSelected(s.step, s.move);
}

}  // namespace taiwa::ui
