// The clipboard of the graphical editors: elements as a PLCopen fragment in QMimeData, read back
// with fresh localIds (renumbering tested as a table), and everything that is not a fragment of
// the editor's language refused with a message.
#include "editors/common/diagramclipboard.h"
#include "model/plcopen/fragment.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>
#include <QTest>

using namespace iec;
using namespace iec::editors;

namespace {

// "5 7<-5 9<-5,3" : elements 5, 7 and 9; 7 is fed by 5, 9 by 5 and 3. Contacts carry the wires.
std::vector<model::Element> elementsFrom(const QString &spec)
{
    std::vector<model::Element> elements;
    for (const QString &word : spec.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        model::Contact contact;
        contact.localId = word.section(QStringLiteral("<-"), 0, 0).toULongLong();
        contact.variable = QStringLiteral("X%1").arg(contact.localId);
        contact.connectionPointIn = model::ConnectionPointIn {};
        contact.connectionPointOut = model::ConnectionPointOut {};
        const QString sources = word.section(QStringLiteral("<-"), 1);
        for (const QString &source : sources.split(QLatin1Char(','), Qt::SkipEmptyParts))
            contact.connectionPointIn->connections.push_back({.refLocalId = source.toULongLong()});
        elements.push_back(contact);
    }
    return elements;
}

QString specOf(const std::vector<model::Element> &elements)
{
    QStringList words;
    for (const model::Element &element : elements) {
        const auto &contact = std::get<model::Contact>(element);
        QStringList sources;
        for (const model::Connection &c : contact.connectionPointIn->connections)
            sources << QString::number(c.refLocalId);
        words << QString::number(contact.localId) + (sources.isEmpty() ? QString() : QStringLiteral("<-") + sources.join(QLatin1Char(',')));
    }
    return words.join(QLatin1Char(' '));
}

} // namespace

class TestDiagramClipboard : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void renumbering_data()
    {
        QTest::addColumn<QString>("elements");
        QTest::addColumn<int>("firstFree");
        QTest::addColumn<QString>("renumbered");
        QTest::newRow("one") << "5" << 20 << "20";
        QTest::newRow("wires inside follow") << "5 7<-5 9<-7" << 20 << "20 21<-20 22<-21";
        QTest::newRow("wires to the outside go") << "5 7<-5,3 9<-2" << 20 << "20 21<-20 22";
        QTest::newRow("order kept, not sorted") << "9 5<-9 7<-5,9" << 1 << "1 2<-1 3<-2,1";
        QTest::newRow("localId 0") << "0 1<-0" << 10 << "10 11<-10";
        QTest::newRow("nothing") << "" << 4 << "";
    }

    void renumbering()
    {
        QFETCH(QString, elements);
        QFETCH(int, firstFree);
        QFETCH(QString, renumbered);
        std::vector<model::Element> list = elementsFrom(elements);
        const auto map = renumberElements(list, quint64(firstFree));
        QCOMPARE(specOf(list), renumbered);
        QCOMPARE(map.size(), list.size());
    }

    void copiedElementsComeBackWithFreshIds()
    {
        std::vector<model::Element> elements = elementsFrom(QStringLiteral("5 7<-5 9<-7,3"));
        auto &contact = std::get<model::Contact>(elements[1]);
        contact.negated = true;
        contact.documentation = model::FormattedText {QStringLiteral("Seal-in"), {}};
        contact.addData.push_back({QStringLiteral("https://example.org/x"), QStringLiteral("preserve"), QStringLiteral("<x a=\"1\"/>")});
        model::ActionBlock block;
        block.localId = 11;
        model::ActionBlockAction action;
        action.localId = 12;
        action.reference = model::Reference {QStringLiteral("Fill")};
        block.actions.push_back(action);
        elements.push_back(block);
        copyElementsToClipboard(EditorLanguage::LD, elements);
        const QMimeData *data = QGuiApplication::clipboard()->mimeData();
        QVERIFY(data->hasFormat(QString::fromLatin1(kElementsMimeType)));
        QVERIFY(data->text().contains(QStringLiteral("<fragment")));
        QVERIFY(clipboardHasElements());
        const PastedElements pasted = elementsFromClipboard(EditorLanguage::LD, 100);
        QVERIFY2(pasted.ok(), qPrintable(pasted.error));
        std::vector<model::Element> expected = elements;
        renumberElements(expected, 100);
        QVERIFY(pasted.elements == expected);
        QCOMPARE(specOf({pasted.elements.begin(), pasted.elements.begin() + 3}), QStringLiteral("100 101<-100 102<-101"));
        QCOMPARE(std::get<model::ActionBlock>(pasted.elements[3]).localId, quint64(103));
        QCOMPARE(std::get<model::ActionBlock>(pasted.elements[3]).actions.front().localId, quint64(104));
        // The text alone (copied through a text editor) is read too.
        QMimeData text;
        text.setText(data->text());
        QVERIFY(elementsFromMimeData(&text, EditorLanguage::LD, 100).elements == expected);
    }

    void whatIsNotAFragmentOfTheLanguageIsRefused_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("error");
        const QString ours = QString::fromLatin1(kElementsMimeType);
        const QString text = QStringLiteral("text/plain");
        QTest::newRow("empty") << text << QByteArray() << QStringLiteral("There is nothing to paste.");
        QTest::newRow("text") << text << QByteArray("Start AND NOT Stop")
                              << QStringLiteral("The clipboard holds text, not SFC elements: nothing was pasted.");
        QTest::newRow("another tool's XML") << text << QByteArray("<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"/>")
                                            << QStringLiteral("The clipboard holds no SFC elements that can be pasted. It is XML with a <project> root, not elements copied in IEC Studio.");
        QTest::newRow("malformed") << ours << QByteArray("<fragment language=\"SFC\"><step localId=\"1\" name=")
                                   << QStringLiteral("The clipboard holds no SFC elements that can be pasted. It is not well-formed XML: Error parsing element attribute.");
        QTest::newRow("another language") << ours
                                          << model::plcopen::writeElementsFragment(QStringLiteral("LD"), elementsFrom(QStringLiteral("1")))
                                          << QStringLiteral("The clipboard holds LD elements, which cannot be pasted into SFC.");
        QTest::newRow("an empty fragment") << ours << model::plcopen::writeElementsFragment(QStringLiteral("SFC"), {})
                                           << QStringLiteral("There is nothing to paste.");
    }

    void whatIsNotAFragmentOfTheLanguageIsRefused()
    {
        QFETCH(QString, format);
        QFETCH(QByteArray, bytes);
        QFETCH(QString, error);
        QMimeData data;
        data.setData(format, bytes);
        const PastedElements pasted = elementsFromMimeData(&data, EditorLanguage::SFC, 1);
        QCOMPARE(pasted.error, error);
        QVERIFY(pasted.elements.empty());
        QCOMPARE(elementsFromMimeData(nullptr, EditorLanguage::SFC, 1).error, QStringLiteral("There is nothing to paste."));
    }
};

QTEST_MAIN(TestDiagramClipboard)
#include "tst_diagramclipboard.moc"
