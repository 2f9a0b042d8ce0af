#pragma once

#include "interpreter/runtime/snapshot.h"

#include <QToolBar>

#include <optional>

class QLabel;
class QSlider;
class QSpinBox;

namespace iec::app {

class DocumentArea;
class OnlineController;

// Going back in time, while online: a slider over the scans the runtime keeps (the oldest to
// the present), the scan shown, the memory the history takes, "Present" and "Resume from
// Here". Showing an earlier scan stops a Run and paints every view with that scan's values,
// marked as history: an amber label beside the editor tabs, the status bar and the watch
// pane's value column say so. Resume from Here makes that scan the present and drops the
// scans after it, so the program goes on from there (with new inputs, say).
class HistoryBar : public QToolBar
{
    Q_OBJECT

public:
    HistoryBar(OnlineController &online, DocumentArea &documents, QWidget *parent = nullptr);

    void retranslate();

    // For tests.
    [[nodiscard]] QSlider *slider() const { return m_slider; }
    [[nodiscard]] QAction *presentAction() const { return m_present; }
    [[nodiscard]] QAction *resumeAction() const { return m_resume; }
    [[nodiscard]] QLabel *infoLabel() const { return m_info; }
    [[nodiscard]] QLabel *banner() const { return m_banner; }

private:
    void showSnapshot(const interp::RuntimeSnapshot &snapshot);
    void onlineChanged(bool online);
    void sliderMoved(int cycle);
    void updateTexts();

    OnlineController &m_online;
    DocumentArea &m_documents;
    QLabel *m_title;
    QSlider *m_slider;
    QLabel *m_scan;
    QLabel *m_info;
    QAction *m_present;
    QAction *m_resume;
    QLabel *m_banner; // beside the editor tabs while showing the past
    std::optional<int> m_shown;
    int m_presentCycle = 0;
    interp::HistoryInfo m_history;
    bool m_updating = false;
};

} // namespace iec::app
