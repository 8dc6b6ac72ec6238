package robosim.aria;

import java.io.IOException;
import java.io.InputStream;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * ARIA's {@code ArKeyHandler}: single key presses from the terminal, each handled by the callback
 * added for it (ArKeyHandler.h, ArKeyHandler.cpp). On a terminal it puts it in raw mode (keys come
 * at once, unechoed) while it has the keys, and restores it after; from a file or a pipe it reads
 * the bytes as they come. Arrow, function and other special keys arrive as the terminal's escape
 * sequences and are given as ARIA's codes ({@link #UP}, {@link #ESCAPE}, ...); other keys as their
 * characters.
 *
 * <p>A robot checks the keys each cycle once the handler is attached ({@link
 * ArRobot#attachKeyHandler}); a program without a robot calls {@link #checkKeys()}.
 */
public class ArKeyHandler {
    /** The up arrow. */
    public static final int UP = 256;
    /** The down arrow. */
    public static final int DOWN = 257;
    /** The left arrow. */
    public static final int LEFT = 258;
    /** The right arrow. */
    public static final int RIGHT = 259;
    /** Escape alone. */
    public static final int ESCAPE = 260;
    /** The space bar. */
    public static final int SPACE = 261;
    /** Tab. */
    public static final int TAB = 262;
    /** Enter or return. */
    public static final int ENTER = 263;
    /** Backspace. */
    public static final int BACKSPACE = 264;
    /** F1; F2 to F12 follow it. */
    public static final int F1 = 266;
    /** F2. */
    public static final int F2 = 267;
    /** F3. */
    public static final int F3 = 268;
    /** F4. */
    public static final int F4 = 269;
    /** F5. */
    public static final int F5 = 270;
    /** F6. */
    public static final int F6 = 271;
    /** F7. */
    public static final int F7 = 272;
    /** F8. */
    public static final int F8 = 273;
    /** F9. */
    public static final int F9 = 274;
    /** F10. */
    public static final int F10 = 275;
    /** F11. */
    public static final int F11 = 276;
    /** F12. */
    public static final int F12 = 277;
    /** Page up. */
    public static final int PAGEUP = 279;
    /** Page down. */
    public static final int PAGEDOWN = 280;
    /** Home. */
    public static final int HOME = 281;
    /** End. */
    public static final int END = 282;
    /** Insert. */
    public static final int INSERT = 283;
    /** Delete (forward). */
    public static final int DEL = 284;

    /** How long the rest of an escape sequence may take to come, ms: ARIA's. */
    private static final long NEXT_KEY_MS = 10;
    private static final int EOF = -2;

    private final Map<Integer, Runnable> handlers = new ConcurrentHashMap<>();
    private final LinkedBlockingQueue<Integer> bytes = new LinkedBlockingQueue<>();
    private final InputStream stream;
    private final boolean terminal;
    private volatile boolean blocking;
    private volatile boolean restored = true;
    private volatile Thread reader;
    private volatile String savedTerminal;
    private int saved = -1;

    /** A handler of the terminal's keys (standard input), taking them now, as ARIA's default. */
    public ArKeyHandler() {
        this(false, true, null, true);
    }

    /**
     * @param blocking              whether {@link #getKey()} waits for a key
     * @param addAriaExitCB         whether {@link Aria#exit} restores the terminal
     * @param stream                where keys come from; null for standard input (a terminal is
     *                              put in raw mode)
     * @param takeKeysInConstructor whether it takes the keys now, or at {@link #takeKeys}
     */
    public ArKeyHandler(boolean blocking, boolean addAriaExitCB, InputStream stream, boolean takeKeysInConstructor) {
        this.stream = stream != null ? stream : System.in;
        this.terminal = stream == null && System.console() != null;
        this.blocking = blocking;
        if (addAriaExitCB) {
            Aria.addExitCallback(this::restore, 50);
        }
        if (takeKeysInConstructor) {
            takeKeys(blocking);
        }
    }

    /**
     * @param key     a key: a character, or one of the codes ({@link #UP}, ...)
     * @param handler what to do when it is pressed
     * @return false if the key has a handler already (logged)
     */
    public boolean addKeyHandler(int key, Runnable handler) {
        if (handlers.putIfAbsent(key, handler) != null) {
            if (key >= '!' && key <= '~') {
                ArLog.log(ArLog.Normal, "There is already a key to handle '%c' which is number %d 0x%x", (char) key, key,
                        key);
            } else {
                ArLog.log(ArLog.Normal, "There is already a key to handle number %d 0x%x", key, key);
            }
            return false;
        }
        return true;
    }

    /** @param key a key @return whether it had a handler, now removed */
    public boolean remKeyHandler(int key) {
        return handlers.remove(key) != null;
    }

    /** @param handler a handler @return whether some key had it, now removed */
    public boolean remKeyHandler(Runnable handler) {
        return handlers.values().removeIf(h -> h == handler);
    }

    /**
     * Takes the keys: a terminal goes to raw mode, and keys are read from now on.
     *
     * @param blockingRead whether {@link #getKey()} waits for a key
     */
    public synchronized void takeKeys(boolean blockingRead) {
        blocking = blockingRead;
        if (!restored) {
            return;
        }
        restored = false;
        if (terminal) {
            savedTerminal = stty("-g");
            stty("-icanon", "-echo", "min", "1");
        }
        if (reader == null) {
            Thread t = new Thread(this::read, "key handler");
            t.setDaemon(true);
            reader = t;
            t.start();
        }
    }

    private void read() {
        try {
            int b;
            while ((b = stream.read()) != -1) {
                bytes.add(b);
            }
        } catch (IOException e) {
            ArLog.log(ArLog.Verbose, "ArKeyHandler: reading keys ended: %s", e.getMessage());
        }
        bytes.add(EOF);
    }

    /** Gives the terminal back as it was; no keys are read after. */
    public synchronized void restore() {
        if (restored) {
            return;
        }
        restored = true;
        if (terminal && savedTerminal != null) {
            stty(savedTerminal.trim());
        }
    }

    /** Runs {@code stty} on the controlling terminal; its output, or null if it could not run. */
    private static String stty(String... args) {
        String[] command = new String[args.length + 1];
        command[0] = "stty";
        System.arraycopy(args, 0, command, 1, args.length);
        try {
            Process p = new ProcessBuilder(command).redirectInput(ProcessBuilder.Redirect.INHERIT).start();
            String out = new String(p.getInputStream().readAllBytes());
            return p.waitFor(5, TimeUnit.SECONDS) && p.exitValue() == 0 ? out : null;
        } catch (IOException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    /** Handles every key waiting, each with its handler if it has one. */
    public void checkKeys() {
        int key;
        while (!restored && (key = getKey()) != -1) {
            Runnable h = handlers.get(key);
            if (h != null) {
                h.run();
            }
        }
    }

    /**
     * The next key, as ARIA reads it: escape sequences become ARIA's codes.
     *
     * @return the key, or -1 if none is waiting (when not blocking) or the input has ended
     */
    public int getKey() {
        int key = getChar(blocking ? Long.MAX_VALUE : 0);
        switch (key) {
            case -1, 0:
                return -1;
            case ' ':
                return SPACE;
            case '\t':
                return TAB;
            case 10, 13:
                return ENTER;
            case 8, 127:
                return BACKSPACE;
            case 27:
                return escaped();
            default:
                return key;
        }
    }

    private int escaped() {
        int key = getChar(NEXT_KEY_MS);
        if (key == -1) {
            return ESCAPE;
        }
        if (key == 'O') {
            return switch (getChar(NEXT_KEY_MS)) {
                case 'P' -> F1;
                case 'Q' -> F2;
                case 'R' -> F3;
                case 'S' -> F4;
                case 'F' -> END;
                case 'H' -> HOME;
                default -> -1;
            };
        }
        if (key != '[') {
            return -1;
        }
        int[] k = {-1, -1, -1, -1, -1};
        for (int i = 0; i < k.length; i++) {
            k[i] = getChar(NEXT_KEY_MS);
            if (k[i] == -1 || k[i] == 27 || k[i] == '~' || (i == 0 && k[i] >= 'A' && k[i] <= 'D')) {
                break;
            }
        }
        if (k[k.length - 1] == 27) {
            saved = 27;
        }
        return switch (k[0]) {
            case 'A' -> UP;
            case 'B' -> DOWN;
            case 'C' -> RIGHT;
            case 'D' -> LEFT;
            case '3' -> DEL;
            case '5' -> PAGEUP;
            case '6' -> PAGEDOWN;
            case '2' -> switch (k[1]) {
                case '~' -> INSERT;
                case '0' -> F9;
                case '1' -> F10;
                case '3' -> F11;
                case '4' -> F12;
                default -> -1;
            };
            case '1' -> switch (k[1]) {
                case '5' -> F5;
                case '7' -> F6;
                case '8' -> F7;
                case '9' -> F8;
                default -> -1;
            };
            default -> -1;
        };
    }

    /** The next byte, waiting at most the time given (ms), or -1. */
    private int getChar(long waitMs) {
        if (saved != -1) {
            int c = saved;
            saved = -1;
            return c;
        }
        try {
            Integer b = waitMs <= 0 ? bytes.poll() : bytes.poll(waitMs, TimeUnit.MILLISECONDS);
            if (b == null) {
                return -1;
            }
            if (b == EOF) {
                bytes.add(EOF); // the end stays the end
                return -1;
            }
            return b;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return -1;
        }
    }
}
