package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.protocol.CapturedLog;

/**
 * ArRobot's hold on its actions (ARIA's ArRobot.cpp): deactivating them all, the resolver that
 * combines them, what they wanted at the last cycle and logging it; and the tasks and the lock of
 * the cycle they run in.
 */
class ArRobotActionsTest {
    private final ArRobot robot = Cycles.p3dxRobot();

    @Test
    void deactivateActionsLeavesThemAddedButSilent() {
        ArActionConstantVelocity forward = new ArActionConstantVelocity("forward", 300);
        robot.addAction(forward, 50);
        Cycles.cycle(robot, 100, 0, 0, 0);
        assertEquals(300, robot.getActionDesired().getVel());

        robot.deactivateActions();
        assertFalse(forward.isActive());
        assertSame(forward, robot.findAction("forward"), "still added");
        Cycles.cycle(robot, 200, 0, 0, 0);
        assertFalse(robot.getActionDesired().isAnythingDesired(), "nothing fired");
    }

    @Test
    void getActionDesiredIsACopyOfWhatTheActionsWantedCombined() {
        assertFalse(robot.getActionDesired().isAnythingDesired(), "before any cycle");
        robot.addAction(new ArActionConstantVelocity("forward", 300), 50);
        Cycles.cycle(robot, 100, 0, 0, 0);
        ArActionDesired d = robot.getActionDesired();
        assertEquals(300, d.getVel());
        assertEquals(0, d.getDeltaHeading());
        d.setVel(1);
        assertEquals(300, robot.getActionDesired().getVel(), "changing the copy changes nothing");
    }

    @Test
    void theResolverIsAriasPriorityResolverUntilAnotherIsSet() {
        assertInstanceOf(ArPriorityResolver.class, robot.getResolver());
        assertTrue(robot.getResolver().getDescription().startsWith("Resolves by priority"),
                robot.getResolver().getDescription());
        List<Integer> seen = new ArrayList<>();
        ArResolver slow = new ArResolver("slow", "always 100 mm/s") {
            @Override
            public ArActionDesired resolve(List<Entry> actions, ArRobot r, boolean logActions) {
                seen.add(actions.size());
                ArActionDesired d = new ArActionDesired();
                d.setVel(100);
                return d;
            }
        };
        robot.addAction(new ArActionConstantVelocity("forward", 300), 50);
        robot.setResolver(slow);
        assertSame(slow, robot.getResolver());
        assertEquals("always 100 mm/s", slow.getDescription());
        Cycles.cycle(robot, 100, 0, 0, 0);
        assertEquals(List.of(1), seen, "the robot's resolver combines its actions each cycle");
        assertEquals(100, robot.getActionDesired().getVel());
        assertThrows(NullPointerException.class, () -> robot.setResolver(null));
    }

    @Test
    void withLogActionsEachCycleLogsWhatEachActionWanted() {
        robot.addAction(new ArActionConstantVelocity("forward", 300), 50);
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            Cycles.cycle(robot, 100, 0, 0, 0);
            assertEquals(List.of(), log.lines(), "off by default");
            robot.setLogActions(true);
            Cycles.cycle(robot, 200, 0, 0, 0);
            assertEquals(1, log.lines().size(), log.lines().toString());
            assertTrue(log.lines().get(0).startsWith("priority 50, forward: "), log.lines().get(0));
            robot.setLogActions(false);
            Cycles.cycle(robot, 300, 0, 0, 0);
            assertEquals(1, log.lines().size());
        }
    }

    @Test
    void aRemovedSensorInterpretationTaskRunsNoMore() {
        List<Long> runs = new ArrayList<>();
        robot.addSensorInterpTask("count", 50, () -> runs.add(robot.getCounter()));
        Cycles.cycle(robot, 100, 0, 0, 0);
        assertTrue(robot.remSensorInterpTask("count"));
        assertFalse(robot.remSensorInterpTask("count"), "already gone");
        Cycles.cycle(robot, 200, 0, 0, 0);
        assertEquals(List.of(1L), runs);
    }

    @Test
    void tryLockTakesTheCyclesLockOnlyWhenItIsFree() throws Exception {
        assertTrue(robot.tryLock());
        try {
            assertTrue(robot.tryLock(), "the lock is re-entrant for its holder");
            robot.unlock();
            CompletableFuture<Boolean> other = CompletableFuture.supplyAsync(robot::tryLock);
            assertFalse(other.get(10, TimeUnit.SECONDS), "held by this thread");
        } finally {
            robot.unlock();
        }
        CompletableFuture<Boolean> after = CompletableFuture.supplyAsync(() -> {
            boolean got = robot.tryLock();
            if (got) {
                robot.unlock();
            }
            return got;
        });
        assertTrue(after.get(10, TimeUnit.SECONDS), "free again");
    }

    @Test
    void anActionWithoutAKeptDesireAnswersNull() {
        ArAction bare = new ArAction("bare", "does nothing") {
            @Override
            public ArActionDesired fire(ArActionDesired currentDesired) {
                return null;
            }
        };
        assertNull(bare.getDesired());
        assertEquals("does nothing", bare.getDescription());
    }
}
