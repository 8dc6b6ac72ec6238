package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** ARIA's threading tools: ArMutex, ArCondition, ArThread and ArASyncTask, with ARIA's codes. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ArThreadToolsTest {
    @Test
    void aRecursiveMutexIsLockedAgainByItsHolderAndRefusedToOthers() throws Exception {
        ArMutex m = new ArMutex();
        assertEquals(0, m.lock());
        assertEquals(0, m.lock());
        assertEquals(ArMutex.STATUS_ALREADY_LOCKED,
                CompletableFuture.supplyAsync(m::tryLock).get(10, TimeUnit.SECONDS));
        assertEquals(0, m.unlock());
        assertEquals(0, m.unlock());
        assertEquals(ArMutex.STATUS_FAILED, m.unlock(), "not held any more");
        assertEquals(0, CompletableFuture.supplyAsync(() -> {
            int r = m.tryLock();
            m.unlock();
            return r;
        }).get(10, TimeUnit.SECONDS));
        assertEquals("Mutex already locked", m.getError(ArMutex.STATUS_ALREADY_LOCKED));
    }

    @Test
    void aNonRecursiveMutexRefusesItsHoldersSecondLockInsteadOfDeadlocking() {
        ArMutex m = new ArMutex(false);
        m.setLogName("plain");
        assertEquals(0, m.lock());
        assertEquals(ArMutex.STATUS_ALREADY_LOCKED, m.lock());
        assertEquals(ArMutex.STATUS_ALREADY_LOCKED, m.tryLock());
        assertEquals(0, m.unlock());
        assertEquals("plain", m.getLogName());
    }

    @Test
    void aSignalWithNobodyWaitingIsLostAsInAria() {
        ArCondition c = new ArCondition();
        assertEquals(0, c.signal());
        assertEquals(ArCondition.STATUS_WAIT_TIMEDOUT, c.timedWait(50));
        assertEquals("unnamed", c.getLogName());
        assertEquals("The timedwait timed out before signaling", c.getError(ArCondition.STATUS_WAIT_TIMEDOUT));
    }

    @Test
    void aSignalWakesOneWaiterAndABroadcastWakesAll() throws Exception {
        ArCondition c = new ArCondition();
        CompletableFuture<Integer> one = CompletableFuture.supplyAsync(c::await);
        // a signal before the waiter waits is lost: signal until it has woken
        while (!one.isDone()) {
            c.signal();
            Thread.sleep(5);
        }
        assertEquals(0, one.get(10, TimeUnit.SECONDS));

        CompletableFuture<Integer> a = CompletableFuture.supplyAsync(() -> c.timedWait(20_000));
        CompletableFuture<Integer> b = CompletableFuture.supplyAsync(() -> c.timedWait(20_000));
        while (!(a.isDone() && b.isDone())) {
            c.broadcast();
            Thread.sleep(5);
        }
        assertEquals(0, a.get());
        assertEquals(0, b.get());
    }

    @Test
    void anInterruptedWaitSaysSoAndKeepsTheInterrupt() throws Exception {
        ArCondition c = new ArCondition();
        AtomicInteger code = new AtomicInteger(-1);
        AtomicInteger stillInterrupted = new AtomicInteger();
        Thread t = new Thread(() -> {
            Thread.currentThread().interrupt();
            code.set(c.await());
            stillInterrupted.set(Thread.currentThread().isInterrupted() ? 1 : 0);
        });
        t.start();
        t.join(10_000);
        assertEquals(ArCondition.STATUS_WAIT_INTR, code.get());
        assertEquals(1, stillInterrupted.get());
    }

    /** Counts while it runs, as ARIA's tasks poll their running flag. */
    static final class Counter extends ArASyncTask {
        final AtomicInteger count = new AtomicInteger();
        volatile ArThread seenAsSelf;
        volatile Object arg;

        @Override
        public Object runThread(Object arg) {
            this.arg = arg;
            seenAsSelf = ArThread.self();
            while (getRunningWithLock() && count.incrementAndGet() < 1_000_000) {
                Thread.onSpinWait();
            }
            return null;
        }
    }

    @Test
    void anAsyncTaskRunsUntilStoppedAndIsJoined() {
        Counter task = new Counter();
        task.setThreadName("counter");
        task.runAsync();
        while (task.count.get() < 10) {
            Thread.onSpinWait();
        }
        assertTrue(task.getRunning());
        assertEquals(ArThread.STATUS_FAILED, task.create(true, true), "created once only");
        task.stopRunning();
        assertEquals(0, task.join());
        assertTrue(task.isThreadStarted());
        assertTrue(task.isThreadFinished());
        assertSame(task, task.seenAsSelf);
        assertEquals("counter", task.getThread().getName());
        assertTrue(task.getThread().isDaemon(), "an ARIA program ends when its main does");
        assertNull(ArThread.self(), "the test's thread is none of ARIA's");
    }

    @Test
    void runRunsTheTaskInTheCallingThreadWithItsArgument() {
        Counter task = new Counter();
        task.count.set(999_990);
        assertNull(task.runInThisThread("go"));
        assertEquals("go", task.arg);
        assertEquals(1_000_000, task.count.get());
        assertEquals(ArThread.STATUS_NO_SUCH_THREAD, task.join(), "no thread was made");
    }

    @Test
    void aThreadCannotJoinItselfNorADetachedOne() throws Exception {
        AtomicInteger self = new AtomicInteger(-1);
        ArThread[] holder = new ArThread[1];
        java.util.concurrent.CountDownLatch made = new java.util.concurrent.CountDownLatch(1);
        holder[0] = new ArThread(() -> {
            try {
                made.await();
            } catch (InterruptedException e) {
                return;
            }
            self.set(holder[0].join());
        }, true);
        made.countDown();
        assertEquals(0, holder[0].join());
        assertEquals(ArThread.STATUS_JOIN_SELF, self.get());
        assertEquals(0, holder[0].detach());
        assertEquals(ArThread.STATUS_ALREADY_DETATCHED, holder[0].detach());
        assertEquals(ArThread.STATUS_INVALID, holder[0].join());
        assertFalse(holder[0].getJoinable());
    }
}
