// What a person would see cut off on a screen, found by walking its widgets: labels, buttons and
// header sections narrower than their text, table cells narrower than their value, tables whose
// columns do not all fit, and plots lower than a plot can be read at. And the texts a screen
// shows, to find words left in English.
#pragma once

#include <QAbstractButton>
#include <QAbstractItemModel>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QFontMetrics>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsTextItem>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QListView>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QStyle>
#include <QTabBar>
#include <QTableView>
#include <QTextDocument>
#include <QToolButton>
#include <QWidget>
#include <QtCharts/QValueAxis>

namespace armtrack::gui::test {

/// The lowest a plot may be (px) and still show its curve and a few ticks.
inline constexpr int kMinPlotHeight = 120;

/// Whether w is shown to the user inside root: visible, with a size, and not scrolled or
/// clipped entirely out of its scroll areas' view.
inline bool shownIn(const QWidget* w, const QWidget* root) {
  if (!w->isVisibleTo(root) || w->width() <= 0 || w->height() <= 0) return false;
  for (const QWidget* p = w->parentWidget(); p && p != root; p = p->parentWidget())
    if (p->width() <= 0 || p->height() <= 0) return false;  // a collapsed splitter pane
  return true;
}

inline QString describe(const QWidget* w) {
  QString name = w->accessibleName();
  if (name.isEmpty()) name = w->objectName();
  return QStringLiteral("%1 \"%2\"").arg(QString::fromLatin1(w->metaObject()->className()), name);
}

inline QString plainText(const QLabel* l) {
  if (Qt::mightBeRichText(l->text()) && l->textFormat() != Qt::PlainText) {
    QTextDocument d;
    d.setHtml(l->text());
    return d.toPlainText();
  }
  return l->text();
}

/// Every text of root that is cut: one line per problem, empty when none. Tables named in
/// wholeTables must show all their columns without scrolling sideways.
inline QStringList clippedTexts(QWidget* root, const QStringList& wholeTables = {}) {
  QStringList problems;
  const auto check = [&](const QWidget* w, const QString& text, int need, int have) {
    if (need > have + 1)
      problems << QStringLiteral("%1: \"%2\" needs %3 px, has %4")
                      .arg(describe(w), text)
                      .arg(need)
                      .arg(have);
  };
  for (QLabel* l : root->findChildren<QLabel*>()) {
    if (!shownIn(l, root) || l->text().isEmpty() || l->pixmap().isNull() == false) continue;
    QString text = plainText(l);
    if (l->buddy() || l->textFormat() != Qt::PlainText)
      text.replace(QLatin1String("&&"), QStringLiteral("\x01")).remove(u'&').replace(u'\x01', u'&');
    if (text.trimmed().isEmpty()) continue;
    if (text.contains(QChar(0x2026)) && !text.contains(QLatin1String("...")))
      problems << QStringLiteral("%1: elided \"%2\"").arg(describe(l), text);
    const QFontMetrics fm(l->font());
    const QRect room =
        l->contentsRect().adjusted(l->margin(), l->margin(), -l->margin(), -l->margin());
    if (l->wordWrap()) {
      const QRect need = fm.boundingRect(QRect(0, 0, room.width(), 100000), Qt::TextWordWrap, text);
      check(l, text, need.width(), room.width());
      if (need.height() > room.height() + 2)
        problems << QStringLiteral("%1: \"%2\" needs %3 px high, has %4")
                        .arg(describe(l), text)
                        .arg(need.height())
                        .arg(room.height());
    } else {
      int widest = 0;
      for (const QString& line : text.split(QLatin1Char('\n')))
        widest = std::max(widest, fm.horizontalAdvance(line));
      check(l, text, widest, room.width());
    }
  }
  for (QAbstractButton* b : root->findChildren<QAbstractButton*>()) {
    if (!shownIn(b, root) || b->text().isEmpty() || qobject_cast<QTabBar*>(b->parentWidget()))
      continue;
    QString text = b->text();
    text.remove(QLatin1Char('&'));
    const QFontMetrics fm(b->font());
    int need = fm.horizontalAdvance(text);
    if (!b->icon().isNull()) need += b->iconSize().width() + 4;
    int have = b->width();
    QStyle* s = b->style();
    if (qobject_cast<QCheckBox*>(b))
      have -= s->pixelMetric(QStyle::PM_IndicatorWidth, nullptr, b) +
              s->pixelMetric(QStyle::PM_CheckBoxLabelSpacing, nullptr, b);
    else if (qobject_cast<QRadioButton*>(b))
      have -= s->pixelMetric(QStyle::PM_ExclusiveIndicatorWidth, nullptr, b) +
              s->pixelMetric(QStyle::PM_RadioButtonLabelSpacing, nullptr, b);
    else
      have -= 4;  // the frame
    check(b, text, need, have);
  }
  for (QTableView* t : root->findChildren<QTableView*>()) {
    if (!shownIn(t, root) || !t->model()) continue;
    QAbstractItemModel* m = t->model();
    QHeaderView* h = t->horizontalHeader();
    const QFontMetrics cellFm(t->font());
    const int pad = 2 * (t->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, t) + 1);
    int right = 0;
    for (int c = 0; c < m->columnCount(); ++c) {
      if (t->isColumnHidden(c) || h->isSectionHidden(c)) continue;
      const int width = t->columnWidth(c);
      right = std::max(right, h->sectionViewportPosition(c) + h->offset() + width);
      if (h->isVisible()) {
        const QString title = m->headerData(c, Qt::Horizontal).toString();
        int need = QFontMetrics(h->font()).horizontalAdvance(title) +
                   2 * h->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, h);
        if (h->isSortIndicatorShown() && h->sortIndicatorSection() == c)
          need += h->style()->pixelMetric(QStyle::PM_HeaderMarkSize, nullptr, h);
        if (!title.contains(QLatin1Char('\n'))) check(h, title, need, width);
      }
      const int rows = std::min(m->rowCount(), 300);
      for (int r = 0; r < rows; ++r) {
        const QString text = m->index(r, c).data(Qt::DisplayRole).toString();
        if (text.isEmpty()) continue;
        const int rowHeight = t->rowHeight(r);
        if (t->wordWrap()) {
          const QRect need =
              cellFm.boundingRect(QRect(0, 0, width - pad, 100000), Qt::TextWordWrap, text);
          check(t, QStringLiteral("%1 (row %2, column %3)").arg(text).arg(r).arg(c),
                need.width() + pad, width);
          if (need.height() > rowHeight + 2)
            problems << QStringLiteral("%1: \"%2\" needs %3 px high, row has %4")
                            .arg(describe(t), text)
                            .arg(need.height())
                            .arg(rowHeight);
        } else {
          check(t, QStringLiteral("%1 (row %2, column %3)").arg(text).arg(r).arg(c),
                cellFm.horizontalAdvance(text) + pad, width);
        }
      }
    }
    if (wholeTables.contains(t->accessibleName()) && right > t->viewport()->width() + 1)
      problems << QStringLiteral("%1: columns need %2 px, %3 shown")
                      .arg(describe(t))
                      .arg(right)
                      .arg(t->viewport()->width());
  }
  for (QChartView* v : root->findChildren<QChartView*>()) {
    if (!shownIn(v, root)) continue;
    // Qt Charts shortens what does not fit (axis labels and titles, legend entries) to "...".
    std::vector<std::pair<QRectF, QString>> labels;
    if (v->scene())
      for (const QGraphicsItem* item : v->scene()->items()) {
        if (!item->isVisible()) continue;
        QString text;
        if (const auto* t = dynamic_cast<const QGraphicsTextItem*>(item))
          text = t->toPlainText();
        else if (const auto* t = dynamic_cast<const QGraphicsSimpleTextItem*>(item))
          text = t->text();
        if (text.endsWith(QLatin1String("...")) || text.endsWith(QChar(0x2026)))
          problems << QStringLiteral("%1: plot text cut to \"%2\"").arg(describe(v), text);
        if (!text.isEmpty()) {
          // The text's own box (a text item's bounding rect has a margin around the glyphs).
          const QRectF box = item->sceneBoundingRect().adjusted(4, 4, -4, -4);
          for (const auto& [other, otherText] : labels)
            if (box.intersects(other))
              problems << QStringLiteral("%1: plot texts \"%2\" and \"%3\" overlap")
                              .arg(describe(v), text, otherText);
          labels.emplace_back(box, text);
        }
      }
    if (v->height() < kMinPlotHeight)
      problems << QStringLiteral("%1: plot %2 px high (at least %3)")
                      .arg(describe(v))
                      .arg(v->height())
                      .arg(kMinPlotHeight);
  }
  return problems;
}

/// The texts root shows: labels, buttons, group boxes, tabs, header sections, table cells,
/// combo boxes and window titles.
inline QStringList shownTexts(QWidget* root) {
  QStringList out;
  const auto add = [&](QString s) {
    s.remove(QLatin1Char('&'));
    s = s.trimmed();
    if (!s.isEmpty()) out << s;
  };
  add(root->window()->windowTitle());
  for (QWidget* w : root->findChildren<QWidget*>()) {
    if (!shownIn(w, root)) continue;
    if (auto* l = qobject_cast<QLabel*>(w)) add(plainText(l));
    if (auto* b = qobject_cast<QAbstractButton*>(w)) add(b->text());
    if (auto* g = qobject_cast<QGroupBox*>(w)) add(g->title());
    if (auto* c = qobject_cast<QComboBox*>(w)) add(c->currentText());
    if (auto* t = qobject_cast<QTabBar*>(w))
      for (int i = 0; i < t->count(); ++i) add(t->tabText(i));
    if (auto* h = qobject_cast<QHeaderView*>(w); h && h->model())
      for (int i = 0; i < h->count(); ++i)
        if (!h->isSectionHidden(i)) add(h->model()->headerData(i, h->orientation()).toString());
    if (auto* v = qobject_cast<QListView*>(w); v && v->model())
      for (int r = 0; r < std::min(v->model()->rowCount(), 100); ++r)
        add(v->model()->index(r, 0).data().toString());
    if (auto* t = qobject_cast<QTableView*>(w); t && t->model())
      for (int r = 0; r < std::min(t->model()->rowCount(), 100); ++r)
        for (int c = 0; c < t->model()->columnCount(); ++c)
          if (!t->isColumnHidden(c)) add(t->model()->index(r, c).data().toString());
  }
  return out;
}

}  // namespace armtrack::gui::test
