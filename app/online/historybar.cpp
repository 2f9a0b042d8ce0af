#include "app/online/historybar.h"

#include "app/documentarea.h"
#include "app/online/onlinecontroller.h"

#include <QAction>
#include <QLabel>
#include <QLocale>
#include <QSlider>

namespace iec::app {

HistoryBar::HistoryBar(OnlineController &online, DocumentArea &documents, QWidget *parent)
    : QToolBar(parent)
    , m_online(online)
    , m_documents(documents)
    , m_title(new QLabel(this))
    , m_slider(new QSlider(Qt::Horizontal, this))
    , m_scan(new QLabel(this))
    , m_info(new QLabel(this))
    , m_present(new QAction(this))
    , m_resume(new QAction(this))
    , m_banner(new QLabel(&documents))
{
    setObjectName(QStringLiteral("historyBar"));
    m_slider->setObjectName(QStringLiteral("historySlider"));
    m_slider->setMinimumWidth(320);
    m_slider->setRange(0, 0);
    m_slider->setPageStep(10);
    m_scan->setMinimumWidth(m_scan->fontMetrics().horizontalAdvance(QStringLiteral("0000000 / 0000000")));
    addWidget(m_title);
    addWidget(m_slider);
    addWidget(m_scan);
    addAction(m_present);
    addAction(m_resume);
    addSeparator();
    addWidget(m_info);
    m_banner->setStyleSheet(QStringLiteral("QLabel { background: #ffecb3; color: #7a4a00; font-weight: bold; "
                                           "padding: 2px 8px; border: 1px solid #e09000; }"));
    m_banner->hide();
    documents.setCornerWidget(m_banner, Qt::TopRightCorner);

    connect(m_slider, &QSlider::valueChanged, this, &HistoryBar::sliderMoved);
    connect(m_present, &QAction::triggered, &m_online, &OnlineController::showPresent);
    connect(m_resume, &QAction::triggered, this, [this] {
        if (m_shown)
            m_online.resumeFrom(*m_shown);
    });
    connect(&m_online, &OnlineController::snapshotShown, this,
            [this](std::shared_ptr<const interp::RuntimeSnapshot> snapshot) { showSnapshot(*snapshot); });
    connect(&m_online, &OnlineController::onlineChanged, this, &HistoryBar::onlineChanged);
    onlineChanged(false);
    retranslate();
}

void HistoryBar::retranslate()
{
    setWindowTitle(tr("Scan History"));
    m_title->setText(tr("History: "));
    m_present->setText(tr("Present"));
    m_present->setToolTip(tr("Show the program as it is now"));
    m_resume->setText(tr("Resume from Here"));
    m_resume->setToolTip(tr("Go on from the scan shown: the scans after it are dropped, the next cycle "
                            "starts from its values (write new inputs first, if you like)"));
    m_slider->setToolTip(tr("Drag (or use the arrow keys) to see the program after an earlier scan"));
    updateTexts();
}

void HistoryBar::onlineChanged(bool online)
{
    setVisible(online);
    m_shown.reset();
    m_banner->hide();
    updateTexts();
}

void HistoryBar::showSnapshot(const interp::RuntimeSnapshot &snapshot)
{
    m_shown = snapshot.historyCycle;
    m_presentCycle = snapshot.presentCycle;
    m_history = snapshot.history;
    m_updating = true;
    m_slider->setRange(m_history.firstCycle, std::max(m_history.firstCycle, m_history.lastCycle));
    m_slider->setValue(m_shown.value_or(m_presentCycle));
    m_updating = false;
    updateTexts();
}

void HistoryBar::sliderMoved(int cycle)
{
    if (m_updating || !m_online.isOnline())
        return;
    if (cycle == m_presentCycle)
        m_online.showPresent();
    else
        m_online.showScan(cycle);
}

void HistoryBar::updateTexts()
{
    const bool past = m_shown.has_value();
    m_present->setEnabled(past);
    m_resume->setEnabled(past);
    m_scan->setText(tr("%1 / %2").arg(m_shown.value_or(m_presentCycle)).arg(m_presentCycle));
    const int kept = m_history.lastCycle - m_history.firstCycle + 1;
    m_info->setText(tr("%1 of at most %2 scans kept, %3")
                        .arg(m_online.isOnline() ? kept : 0)
                        .arg(m_history.scanLimit)
                        .arg(QLocale().formattedDataSize(qint64(m_history.bytes))));
    m_banner->setText(past ? tr("History: after scan %1 (the program is at %2)").arg(*m_shown).arg(m_presentCycle)
                           : QString());
    m_banner->setVisible(past);
}

} // namespace iec::app
