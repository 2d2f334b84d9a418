// Colours of the NC view: G/M words, axis words (X Y Z I J K R F S T),
// N sequence numbers, comments in ( ) or after ';', and the control's own
// words by the dialect's rules (its data file's "highlighting": Klartext's
// BLK FORM, CYCL DEF, TOOL CALL as keywords, never as M, F or L words). Only the lines the
// view shows, and a screenful either side, are coloured; the others when
// they are scrolled to (a 200-unit tape has tens of thousands of lines:
// colouring them all through a QSyntaxHighlighter took 200 ms on every new
// program, and a highlighter visits every line even to leave it as it is).
// The colours are set on each line's layout as a QSyntaxHighlighter does.
#pragma once

#include "post/dialect.h"

#include <QObject>
#include <QRegularExpression>
#include <QTextCharFormat>
#include <QTextLayout>

#include <vector>

class QPlainTextEdit;
class QTextDocument;

namespace taiwa::ui {

class NcHighlighter : public QObject {
    Q_OBJECT
public:
    explicit NcHighlighter(QPlainTextEdit* view);
    // Colours `doc`, the view's new document, from its first lines shown.
    void watch(QTextDocument* doc);
    // Colours the lines shown now that are not yet.
    void colourShownLines();
    // Whether a line (block number) is coloured.
    bool coloured(int block) const;
    // The dialect's rules (post::Dialect::highlighting); the lines are coloured again.
    void setRules(const post::Highlighting& rules);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QList<QTextLayout::FormatRange> colours(const QString& text) const;
    QPlainTextEdit* view_;
    std::vector<bool> coloured_;  // by block number, for the text shown
    QMetaObject::Connection changed_, changedLater_;
    QTextCharFormat g_, m_, axis_, seq_, other_, rem_, keyword_;
    QRegularExpression word_, keywords_;  // an address word; the dialect's keywords (none: matches nothing)
};

}  // namespace taiwa::ui
