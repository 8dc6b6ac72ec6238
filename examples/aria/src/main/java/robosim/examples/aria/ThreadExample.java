package robosim.examples.aria;

import robosim.aria.ArASyncTask;
import robosim.aria.ArCondition;
import robosim.aria.ArLog;
import robosim.aria.ArMutex;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code threadExample.cpp}, line for line: ARIA's threading tools. A new thread
 * ({@link ArASyncTask}) counts up once a second under an {@link ArMutex} and signals an
 * {@link ArCondition} at each multiple of ten; the main thread reads the counter until it reaches
 * ten, waits on the condition, then stops the other thread and waits for it to end. No robot: its
 * sleeps are in wall-clock time.
 */
public final class ThreadExample {
    private ThreadExample() {
    }

    /** A subclass of ArASyncTask, to contain a method that runs in a new thread. */
    static final class ExampleThread extends ArASyncTask {
        private final ArCondition myCondition = new ArCondition();
        private final ArMutex myMutex = new ArMutex();
        private int myCounter;

        /** Constructor. Initialize counter. */
        ExampleThread() {
            myCounter = 0;
            myCondition.setLogName("ExampleThreadCondition");
        }

        /*
         * Called in the new thread when launched. It runs in a loop, incrementing the counter each
         * second, locking the mutex to prevent conflicting access by other threads. If it reaches a
         * value divisible by ten, it signals the condition variable.
         */
        @Override
        public Object runThread(Object arg) {
            // Run until the thread is requested to end by another thread.
            while (this.getRunningWithLock()) {
                myMutex.lock();

                // Increment the counter.
                myCounter++;
                ArLog.log(ArLog.Normal, "Example thread: incremented counter to %d.", myCounter);

                // If it's now divisible by 10, signal the condition variable.
                if (myCounter % 10 == 0) {
                    ArLog.log(ArLog.Normal, "Example thread: Signalling condition.");
                    myCondition.signal();
                }

                // Unlock, then sleep. We unlock before the sleep, so that while we are sleeping,
                // other threads that try to lock the mutex won't be blocked.
                myMutex.unlock();
                ArUtil.sleep(1000);
            }

            ArLog.log(ArLog.Normal, "Example thread: requested stop running, ending thread.");
            return null;
        }

        /* Other threads call this to wait for the condition this thread signals. */
        void waitOnCondition() {
            myCondition.await();
            ArLog.log(ArLog.Normal, " %s ArCondition object was signalled, done waiting for it.",
                    myCondition.getLogName());
        }

        /* Get the counter. Not threadsafe, you must lock the mutex during access. */
        int getCounter() {
            return myCounter;
        }

        /* Set the counter. Not threadsafe, you must lock the mutex during access. */
        void setCounter(int ctr) {
            myCounter = ctr;
        }

        /* Lock the mutex object. */
        void lockMutex() {
            myMutex.lock();
        }

        /* Unlock the mutex object. */
        void unlockMutex() {
            myMutex.unlock();
        }
    }

    /** @param args none */
    public static void main(String[] args) {
        Aria.init();

        ExampleThread exampleThread = new ExampleThread();

        // Launch the new thread in the background. This thread (the main program thread) continues
        // immediately after the new thread is created.
        ArLog.log(ArLog.Normal, "Main thread: Running new example thread ...");
        exampleThread.runAsync();

        // Loop, reading the value contained in the ExampleThread object, sleeping each iteration so
        // as not to keep the other thread from the mutex. When the counter reaches 10, break out of
        // the loop and then wait on the condition variable.
        while (true) {
            exampleThread.lockMutex();
            int c = exampleThread.getCounter();
            exampleThread.unlockMutex(); // we can unlock the mutex now, since we made a copy of the counter.

            System.out.printf("Main thread: Counter=%d.%n", c);

            if (c >= 10) {
                break;
            }

            ArUtil.sleep(600);
        }

        // Block on the ArCondition object: it returns only when the other thread signals it.
        ArLog.log(ArLog.Normal, "Main thread: Waiting on condition object...");
        exampleThread.waitOnCondition();

        ArLog.log(ArLog.Normal, "Main thread: Condition was signaled, and execution continued. Telling the other"
                + " thread to stop running.");
        exampleThread.stopRunning();

        ArLog.log(ArLog.Normal, "Main thread: Waiting for the other thread to exit, then exiting the program.");
        do {
            ArUtil.sleep(250);
        } while (exampleThread.getRunningWithLock());

        ArLog.log(ArLog.Normal, "Main thread: Exiting program.");
    }
}
