#include "app/messagespane.h"

#include <QSignalSpy>
#include <QTest>
#include <QTreeView>

using namespace iec::app;

class TestMessagesPane : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void locations_data();
    void locations();
    void sourcesAreReplacedIndependentlyAndErrorsComeFirst();
    void activatingARowEmitsItsMessage();
};

void TestMessagesPane::locations_data()
{
    QTest::addColumn<Message>("message");
    QTest::addColumn<QString>("location");
    QTest::newRow("text") << Message{.pouName = QStringLiteral("Main"), .line = 12, .column = 5}
                          << QStringLiteral("Main, line 12, column 5");
    QTest::newRow("line only") << Message{.pouName = QStringLiteral("Main"), .line = 3}
                               << QStringLiteral("Main, line 3");
    QTest::newRow("element") << Message{.pouName = QStringLiteral("Mixer"), .localId = 42}
                             << QStringLiteral("Mixer, element 42");
    // An inline transition condition: the transition, and where in its text.
    QTest::newRow("element and column") << Message{.pouName = QStringLiteral("Main"), .column = 7, .localId = 2}
                                        << QStringLiteral("Main, element 2, column 7");
    QTest::newRow("whole project") << Message{.text = QStringLiteral("x")} << QString();
}

void TestMessagesPane::locations()
{
    QFETCH(Message, message);
    QFETCH(QString, location);
    QCOMPARE(locationText(message), location);
}

void TestMessagesPane::sourcesAreReplacedIndependentlyAndErrorsComeFirst()
{
    MessagesPane pane;
    MessageListModel &model = pane.model();
    const Message warning{.severity = Message::Severity::Warning, .text = QStringLiteral("unused variable")};
    const Message error{.severity = Message::Severity::Error, .text = QStringLiteral("missing END_IF")};
    const Message info{.severity = Message::Severity::Info, .text = QStringLiteral("vendor data kept")};

    model.setMessages(QStringLiteral("import"), {info});
    model.setMessages(QStringLiteral("build"), {warning, error});
    QCOMPARE(model.rowCount(), 3);
    QCOMPARE(model.message(0), error);
    QCOMPARE(model.message(1), warning);
    QCOMPARE(model.message(2), info);
    QCOMPARE(pane.summary(), QStringLiteral("Errors: 1, warnings: 1"));

    model.setMessages(QStringLiteral("build"), {});
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(model.message(0), info);
    QCOMPARE(model.data(model.index(0, MessageListModel::TextColumn), Qt::DisplayRole).toString(),
             QStringLiteral("vendor data kept"));
    QCOMPARE(pane.summary(), QStringLiteral("Errors: 0, warnings: 0"));
}

void TestMessagesPane::activatingARowEmitsItsMessage()
{
    MessagesPane pane;
    const Message error{.text = QStringLiteral("unknown variable 'Levle'"), .pouName = QStringLiteral("Main"),
                        .line = 7, .column = 3};
    pane.model().setMessages(QStringLiteral("build"), {error});
    QSignalSpy activated(&pane, &MessagesPane::messageActivated);
    auto *view = pane.findChild<QTreeView *>(QStringLiteral("messageList"));

    Q_EMIT view->activated(pane.model().index(0, MessageListModel::LocationColumn));

    QCOMPARE(activated.count(), 1);
    QCOMPARE(activated.at(0).at(0).value<Message>(), error);
}

QTEST_MAIN(TestMessagesPane)
#include "tst_messagespane.moc"
