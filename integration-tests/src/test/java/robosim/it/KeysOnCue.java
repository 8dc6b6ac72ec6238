package robosim.it;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import robosim.aria.ArLog;
import robosim.aria.Aria;

/**
 * A program's keyboard that types keys once the program has printed their cue (after the previous
 * cue), as a person at the terminal waits to see the state before pressing the next key. Its input
 * blocks on what is printed, never on a clock: a cue not printed within a minute ends the input.
 */
final class KeysOnCue extends InputStream {
    /**
     * Keys and what must be printed before they are typed.
     *
     * @param cue  text the program prints
     * @param keys the bytes typed then (an arrow key is three: ESC [ A)
     */
    record Cue(String cue, String keys) {
        /** @param cue text the program prints @param key the one key typed then */
        Cue(String cue, int key) {
            this(cue, String.valueOf((char) key));
        }
    }

    private static final long CUE_WAIT_MS = 60_000;

    private final List<Cue> cues;
    private final StringBuilder printed = new StringBuilder();
    private int next;
    private int searchFrom;
    /** The keys of the cue last seen, still to be read. */
    private String typing = "";

    private KeysOnCue(List<Cue> cues) {
        this.cues = cues;
    }

    /**
     * Runs an example's main as {@link AriaExamplesTest#run} does, with these keys on its standard input.
     *
     * @param cues the keys and their cues, in order
     * @param main the example's main
     * @param args its arguments
     * @return what it printed and the code it gave {@code Aria.exit}
     */
    static AriaExamplesTest.Ran run(List<Cue> cues, Consumer<String[]> main, String... args) {
        KeysOnCue keys = new KeysOnCue(cues);
        synchronized (System.class) {
            InputStream in = System.in;
            System.setIn(keys);
            ArLog.setStream(new PrintStream(keys.sink(), true, StandardCharsets.UTF_8));
            AtomicInteger code = new AtomicInteger(-1);
            Aria.setExitHandler(c -> {
                code.compareAndSet(-1, c);
                throw new AriaExamplesTest.Exited(c);
            });
            try {
                main.accept(args);
            } catch (AriaExamplesTest.Exited e) {
                // the program ended here
            } finally {
                ArLog.setStream(null);
                Aria.setExitHandler(null);
                System.setIn(in);
                keys.close();
            }
            return new AriaExamplesTest.Ran(keys.text(), code.get());
        }
    }

    private OutputStream sink() {
        return new OutputStream() {
            private final java.io.ByteArrayOutputStream line = new java.io.ByteArrayOutputStream();

            @Override
            public void write(int b) {
                synchronized (KeysOnCue.this) {
                    line.write(b);
                    if (b == '\n') {
                        printed.append(line.toString(StandardCharsets.UTF_8));
                        line.reset();
                        KeysOnCue.this.notifyAll();
                    }
                }
            }
        };
    }

    /** Ends the input: the key handler's reader, waiting for a cue, gets the end at once. */
    @Override
    public synchronized void close() {
        next = cues.size();
        typing = "";
        notifyAll();
    }

    private synchronized String text() {
        return printed.toString();
    }

    @Override
    public synchronized int read() throws IOException {
        if (!typing.isEmpty()) {
            char k = typing.charAt(0);
            typing = typing.substring(1);
            return k;
        }
        if (next >= cues.size()) {
            return -1;
        }
        Cue c = cues.get(next);
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CUE_WAIT_MS);
        int at;
        while ((at = printed.indexOf(c.cue(), searchFrom)) < 0) {
            if (next >= cues.size()) {
                return -1; // closed meanwhile
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                next = cues.size();
                return -1;
            }
            try {
                wait(TimeUnit.NANOSECONDS.toMillis(left) + 1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return -1;
            }
        }
        searchFrom = at + c.cue().length();
        next++;
        typing = c.keys().substring(1);
        return c.keys().charAt(0);
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        if (len == 0) {
            return 0;
        }
        int k = read();
        if (k < 0) {
            return -1;
        }
        b[off] = (byte) k;
        return 1;
    }
}
