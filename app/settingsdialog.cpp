#include "app/settingsdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFontComboBox>
#include <QFormLayout>
#include <QSpinBox>
#include <QVBoxLayout>

namespace iec::app {

SettingsDialog::SettingsDialog(const Settings &settings, QWidget *parent)
    : QDialog(parent)
    , m_original(settings)
{
    setWindowTitle(tr("Settings"));

    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("language"));
    m_language->addItem(tr("System language"), QString());
    for (const UiLanguage &language : availableUiLanguages())
        m_language->addItem(language.nativeName, language.localeName);
    m_language->setCurrentIndex(std::max(0, m_language->findData(settings.uiLanguage)));

    m_fontFamily = new QFontComboBox(this);
    m_fontFamily->setObjectName(QStringLiteral("fontFamily"));
    m_fontFamily->setFontFilters(QFontComboBox::MonospacedFonts);
    m_fontFamily->setCurrentFont(settings.editorFont);
    m_fontSize = new QSpinBox(this);
    m_fontSize->setObjectName(QStringLiteral("fontSize"));
    m_fontSize->setRange(6, 48);
    m_fontSize->setSuffix(tr(" pt"));
    m_fontSize->setValue(settings.editorFont.pointSize() > 0 ? settings.editorFont.pointSize() : 10);

    m_gridSize = new QSpinBox(this);
    m_gridSize->setObjectName(QStringLiteral("gridSize"));
    m_gridSize->setRange(2, 100);
    m_gridSize->setSuffix(tr(" px"));
    m_gridSize->setValue(settings.gridSize);

    m_autosave = new QSpinBox(this);
    m_autosave->setObjectName(QStringLiteral("autosave"));
    m_autosave->setRange(0, 120);
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setSpecialValueText(tr("Off"));
    m_autosave->setValue(settings.autosaveMinutes);

    auto *form = new QFormLayout;
    form->addRow(tr("User interface language:"), m_language);
    form->addRow(tr("Editor font:"), m_fontFamily);
    form->addRow(tr("Editor font size:"), m_fontSize);
    form->addRow(tr("Diagram grid size:"), m_gridSize);
    form->addRow(tr("Autosave every:"), m_autosave);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

Settings SettingsDialog::settings() const
{
    Settings result = m_original;
    result.uiLanguage = m_language->currentData().toString();
    result.editorFont = m_fontFamily->currentFont();
    result.editorFont.setPointSize(m_fontSize->value());
    result.gridSize = m_gridSize->value();
    result.autosaveMinutes = m_autosave->value();
    return result;
}

} // namespace iec::app
