// The worker thread's queue of steps is bounded: a solver faster than the
// GUI waits for it instead of burying it in events, and no step is lost.
#include <gtest/gtest.h>

#include <atomic>

#include <QTest>
#include <QThread>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"
#include "ui/widgets/solver_worker.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

TEST_F(Widgets, SolverWaitsWhileTheGuiHasAFullQueue) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-fold.json");
  // The steps the solver itself converges, without the worker.
  int steps = 0;
  ShellSolver(scene, SolverOptions::FromScene(scene.solver)).Solve({[&](const StepState&) {
    ++steps;
    return StepDecision::kContinue;
  }});
  ASSERT_GT(steps, SolverWorker::kQueueLength);
  SolverWorker worker;
  QThread thread;
  worker.moveToThread(&thread);
  thread.start();
  std::atomic<int> sent{0}, last{0};
  bool in_order = true;
  QObject::connect(
      &worker,
      &SolverWorker::stepConverged,
      &worker,
      [&](std::shared_ptr<const StepState> s) {
        in_order = in_order && s->step == last + 1;
        last = s->step;
        ++sent;
      },
      Qt::DirectConnection);  // counted on the worker's thread, as sent
  std::atomic<bool> finished{false};
  QObject::connect(
      &worker, &SolverWorker::finished, &worker, [&] { finished = true; }, Qt::DirectConnection);
  QMetaObject::invokeMethod(
      &worker, [&] { worker.run(scene); }, Qt::QueuedConnection);

  // Nothing is taken off the queue: the solver stops when it is full.
  ASSERT_TRUE(QTest::qWaitFor([&] { return sent == SolverWorker::kQueueLength; }, 30000));
  QTest::qWait(500);
  EXPECT_EQ(sent, SolverWorker::kQueueLength);
  EXPECT_FALSE(finished);

  // Taken one by one, every step comes, in order, and the run ends.
  int taken = 0;
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        for (; taken < sent; ++taken) worker.consumed();
        return finished.load();
      },
      30000));
  EXPECT_EQ(sent, steps);
  EXPECT_TRUE(in_order);
  thread.quit();
  thread.wait();
}

}  // namespace
}  // namespace drape
