// Colours of the NC view: G/M words, axis words (X Y Z I J K R F S T),
// N sequence numbers and comments in ( ) or after ';'.
#pragma once

#include <QSyntaxHighlighter>

namespace taiwa::ui {

class NcHighlighter : public QSyntaxHighlighter {
    Q_OBJECT
public:
    explicit NcHighlighter(QTextDocument* doc);

protected:
    void highlightBlock(const QString& text) override;
};

}  // namespace taiwa::ui
