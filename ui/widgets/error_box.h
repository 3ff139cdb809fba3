// An error shown without blocking: a run or an edit started by a script
// must not wait for someone to click OK.
#pragma once

#include <QMessageBox>
#include <QString>
#include <QWidget>

namespace drape {

inline void ShowError(QWidget* parent, const QString& title, const QString& message) {
  auto* box = new QMessageBox(QMessageBox::Critical, title, message, QMessageBox::Ok, parent);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->show();
}

}  // namespace drape
