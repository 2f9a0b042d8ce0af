#pragma once

#include <QWidget>

namespace iec::editors {

class CodeEditor;

// The gutter left of a CodeEditor: line numbers, diagnostic marks and fold markers. It only
// forwards painting and clicks; the editor knows the blocks.
class LineNumberArea : public QWidget
{
    Q_OBJECT

public:
    explicit LineNumberArea(CodeEditor *editor);

    [[nodiscard]] QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;

private:
    CodeEditor *m_editor;
};

} // namespace iec::editors
