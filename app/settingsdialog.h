#pragma once

#include "app/settings.h"

#include <QDialog>

class QComboBox;
class QFontComboBox;
class QSpinBox;

namespace iec::app {

// Edits a copy of the settings; the caller reads settings() after exec() returns Accepted.
class SettingsDialog : public QDialog
{
    Q_OBJECT

public:
    explicit SettingsDialog(const Settings &settings, QWidget *parent = nullptr);

    [[nodiscard]] Settings settings() const;

private:
    QComboBox *m_language = nullptr;
    QFontComboBox *m_fontFamily = nullptr;
    QSpinBox *m_fontSize = nullptr;
    QSpinBox *m_gridSize = nullptr;
    QSpinBox *m_autosave = nullptr;
    Settings m_original;
};

} // namespace iec::app
