package robosim.panel.process;

import java.util.List;

/**
 * A program for {@link ChildJvmTest}: prints its arguments and a variable, then, with "child",
 * starts a JVM of itself and sleeps, so that a test can see both ended.
 */
public final class Sleeper {
    private Sleeper() {
    }

    /**
     * @param args the words to print; "child" first to start a child that sleeps too
     * @throws Exception if the child cannot be started
     */
    public static void main(String[] args) throws Exception {
        System.out.println("args: " + String.join(" ", args));
        System.out.println("var: " + System.getenv("ROBOSIM_TEST_VAR"));
        if (args.length > 0 && args[0].equals("child")) {
            Process p = new ProcessBuilder(List.of(ChildJvm.javaBinary(), "-cp", System.getProperty("java.class.path"),
                    Sleeper.class.getName(), "sleep")).inheritIO().start();
            System.out.println("child: " + p.pid());
        }
        System.out.flush();
        Thread.sleep(120_000); // the point: a JVM that runs on until it is stopped
    }
}
