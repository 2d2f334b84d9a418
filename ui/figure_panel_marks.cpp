// The figure panel's text and view following each other (figure_panel.h):
// the refusals listed and marked in the text (the line red, the refused word
// underlined), the picked element's statement and the revised corner's
// value marked, a refusal clicked or an element picked putting the cursor
// there, and the cursor on a statement picking its element in the view.
#include "ui/figure_panel.h"

#include "ui/core_messages.h"

#include <QListWidget>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextCursor>

#include <algorithm>

namespace taiwa::ui {

using figure::ContourCorner;

namespace {

const QColor kRefusedLine(0xff, 0xe4, 0xe4);
const QColor kRefusal(0xc0, 0x00, 0x00);
const QColor kStatement(0xff, 0xe8, 0xc8);

// Where the word (a name, a number) or the one character at `at` of `s` ends.
int tokenEnd(const QString& s, int at)
{
    const auto wordChar = [](QChar ch) { return ch.isLetterOrNumber() || ch == '.'; };
    int to = std::min(at + 1, static_cast<int>(s.size()));
    if (at < s.size() && (wordChar(s[at]) || s[at] == '-'))
        while (to < s.size() && wordChar(s[to])) ++to;
    return to;
}

// A refusal as the list shows it, "3:12: why", the why in the station's language.
QString refusalText(const figure::FigureError& e)
{
    return QStringLiteral("%1:%2: %3").arg(e.line).arg(e.column).arg(coreMessage(e.message));
}

// The corner `ref` names, or nullptr.
const ContourCorner* pickedCornerOf(const figure::Evaluation& e, const std::optional<CornerRef>& ref)
{
    if (!ref) return nullptr;
    const figure::EvaluatedContour* c = e.findContour(ref->contour.toStdString());
    if (!c || ref->index < 0 || ref->index >= static_cast<int>(c->corners.size())) return nullptr;
    return &c->corners[static_cast<std::size_t>(ref->index)];
}

}  // namespace

void FigurePanel::listRefusals()
{
    refusals_->clear();
    for (const figure::FigureError& e : errors_) {
        auto* item = new QListWidgetItem(refusalText(e), refusals_);
        item->setData(Qt::UserRole, e.line);
        item->setData(Qt::UserRole + 1, e.column);
        item->setForeground(kRefusal);
    }
}

int FigurePanel::positionOf(int line, int column) const
{
    const QTextBlock b = editor_->document()->findBlockByNumber(line - 1);
    if (!b.isValid()) return editor_->document()->characterCount() - 1;
    const QByteArray bytes = b.text().toUtf8();  // columns count bytes
    const auto n = std::clamp<qsizetype>(column - 1, 0, bytes.size());
    return b.position() + static_cast<int>(QString::fromUtf8(bytes.left(n)).size());
}

// The refused lines in red, the refused word underlined; the picked
// element's statement in the selection's colour (also when the editor has
// not the focus).
void FigurePanel::markLines()
{
    QList<QTextEdit::ExtraSelection> marks;
    QTextDocument* text = editor_->document();
    for (const figure::FigureError& e : errors_) {
        QTextBlock b = text->findBlockByNumber(e.line - 1);
        if (!b.isValid()) b = text->lastBlock();
        QTextEdit::ExtraSelection line;
        line.format.setBackground(kRefusedLine);
        line.format.setProperty(QTextFormat::FullWidthSelection, true);
        line.cursor = QTextCursor(b);
        marks << line;
        // The refused word (a name, a number) or character, underlined.
        QTextEdit::ExtraSelection word;
        const QString s = b.text();
        const int last = std::max(0, static_cast<int>(s.size()) - 1);
        const int at = std::clamp(positionOf(e.line, e.column) - b.position(), 0, last);
        word.cursor = QTextCursor(text);
        word.cursor.setPosition(b.position() + at);
        word.cursor.setPosition(b.position() + tokenEnd(s, at), QTextCursor::KeepAnchor);
        word.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        word.format.setUnderlineColor(kRefusal);
        marks << word;
    }
    const QString picked = view_->selected();
    for (const figure::Definition& d : definitions_) {
        if (QString::fromStdString(d.name) != picked) continue;
        QTextEdit::ExtraSelection statement;
        statement.format.setBackground(kStatement);
        statement.format.setProperty(QTextFormat::FullWidthSelection, true);
        statement.cursor = QTextCursor(text->findBlockByNumber(d.line - 1));
        marks << statement;
    }
    // The value of the corner under revision.
    if (const figure::ContourCorner* corner = pickedCornerOf(evaluation(), picked_)) {
        QTextEdit::ExtraSelection value;
        value.format.setBackground(kStatement);
        value.cursor = valueCursor(*corner);
        marks << value;
    }
    editor_->setExtraSelections(marks);
}

// The corner's value in the text, selected.
QTextCursor FigurePanel::valueCursor(const figure::ContourCorner& corner) const
{
    const QTextBlock b = editor_->document()->findBlockByNumber(corner.line - 1);
    QTextCursor c(editor_->document());
    if (!b.isValid()) return c;
    const int at = positionOf(corner.line, corner.column) - b.position();
    c.setPosition(b.position() + at);
    c.setPosition(b.position() + tokenEnd(b.text(), at), QTextCursor::KeepAnchor);
    return c;
}

void FigurePanel::goToRefusal(QListWidgetItem* item)
{
    if (!item) return;
    QTextCursor c = editor_->textCursor();
    c.setPosition(positionOf(item->data(Qt::UserRole).toInt(), item->data(Qt::UserRole + 1).toInt()));
    editor_->setTextCursor(c);
    editor_->setFocus(Qt::OtherFocusReason);
}

void FigurePanel::select(const QString& name)
{
    // The next pick: a corner picked before is no longer the one in orange.
    if (picked_) {
        picked_.reset();
        showRevision();
    }
    view_->setSelected(name);
    selectStatement(name);
    markLines();
    emit selectionChanged(name);
}

// The statement of `name` selected in the editor, from its name to the end
// of the line (without a trailing comment or blanks).
void FigurePanel::selectStatement(const QString& name)
{
    const auto d = std::find_if(definitions_.begin(), definitions_.end(),
                                [&](const figure::Definition& x) { return QString::fromStdString(x.name) == name; });
    if (d == definitions_.end()) return;
    const QTextBlock b = editor_->document()->findBlockByNumber(d->line - 1);
    if (!b.isValid()) return;
    QString s = b.text();
    if (const auto comment = s.indexOf(QStringLiteral("$$")); comment >= 0) s.truncate(comment);
    while (!s.isEmpty() && s.back().isSpace()) s.chop(1);
    // The cursor at the statement's start (the selection anchored at its
    // end): the editor does not scroll sideways to a long line's end.
    QTextCursor c(editor_->document());
    c.setPosition(b.position() + static_cast<int>(s.size()));
    c.setPosition(positionOf(d->line, d->column), QTextCursor::KeepAnchor);
    updating_ = true;
    editor_->setTextCursor(c);
    editor_->horizontalScrollBar()->setValue(0);
    editor_->ensureCursorVisible();
    updating_ = false;
}

// The cursor on a statement picks its element in the view.
void FigurePanel::onCursorMoved()
{
    if (updating_) return;
    const int line = editor_->textCursor().blockNumber() + 1;
    QString name;
    for (const figure::Definition& d : definitions_)
        if (d.line == line) name = QString::fromStdString(d.name);
    if (name == view_->selected()) return;
    view_->setSelected(name);
    markLines();
    emit selectionChanged(name);
}

}  // namespace taiwa::ui
