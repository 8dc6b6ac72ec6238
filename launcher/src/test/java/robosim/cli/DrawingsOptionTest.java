package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code --drawings} turns on the robots' drawings in the viewer, the replay and GoldFinder's frames. */
class DrawingsOptionTest {
    @Test
    void theViewerDrawsThemOnlyWhenAsked() {
        ViewerCommand on = new ViewerCommand();
        new CommandLine(on).parseArgs("--window", "--drawings");
        assertTrue(on.drawing.render().showDrawings());
        ViewerCommand off = new ViewerCommand();
        new CommandLine(off).parseArgs("--window");
        assertFalse(off.drawing.render().showDrawings());
    }

    @Test
    void theReplayTakesItToo() {
        ReplayCommand replay = new ReplayCommand();
        new CommandLine(replay).parseArgs("run.rsrec", "--png-dir", "out", "--drawings");
        assertTrue(replay.drawing.render().showDrawings());
    }

    @Test
    void goldfinderTakesIt() {
        GoldfinderCommand gold = new GoldfinderCommand();
        new CommandLine(gold).parseArgs("maze.xml", "--drawings");
        assertTrue(gold.drawings);
    }
}
