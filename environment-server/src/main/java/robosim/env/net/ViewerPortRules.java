package robosim.env.net;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Logger;
import robosim.comms.CommsSettings;
import robosim.env.core.Simulation;
import robosim.protocol.Bye;
import robosim.protocol.CommsUpdate;
import robosim.protocol.ControlHello;
import robosim.protocol.ControlRequest;
import robosim.protocol.FrameWriter;
import robosim.protocol.LogLimiter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.ViewerHello;

/**
 * The protocol's rules for the viewer port, part of {@link SessionRules}: a viewer says hello (with
 * the run secret, unless anyone may watch) and then only listens; a control client says hello with
 * the secret and may then change the comms settings and control the run ({@link RunControl}). Both are capped in number, and all viewers'
 * queues share one budget: past it, the viewer furthest behind is dropped, named.
 */
final class ViewerPortRules {
    private static final Logger LOG = Logger.getLogger(SessionRules.class.getName());

    private final CurrentRun run;
    private final Access access;
    private final Limits limits;
    private final List<Connection> viewers = new ArrayList<>();
    private final List<Connection> controls = new ArrayList<>();
    /** Where control requests go: run control, once the server has routed them there. */
    private ControlRequests control = ControlRequests.NONE;
    private final LogLimiter limited;

    ViewerPortRules(CurrentRun run, Access access, Limits limits, LogLimiter limited) {
        this.limited = limited;
        this.run = run;
        this.access = access;
        this.limits = limits;
    }

    private Simulation sim() {
        return run.sim();
    }

    /** @param to where control clients' requests go from now */
    void routeControlTo(ControlRequests to) {
        control = to;
    }

    int viewerCount() {
        return viewers.size();
    }

    /** Sends a snapshot (or a world that changed) to every viewer, encoded once. */
    void broadcast(Message snapshot, MessageCodec codec) {
        viewers.removeIf(Connection::isClosed);
        if (viewers.isEmpty()) {
            return;
        }
        ByteBuffer encoded = FrameWriter.frame(codec, snapshot);
        makeRoomForViewers(encoded.remaining());
        for (Connection v : viewers) {
            v.sendFrame(encoded.duplicate());
        }
    }

    /**
     * Drops the viewer furthest behind, named, until all viewers' queues together, with a frame of
     * the given size more for each, fit the budget (a frame queued for several viewers counts once
     * for each).
     */
    private void makeRoomForViewers(int frameBytes) {
        while (!viewers.isEmpty()) {
            long total = 0;
            Connection slowest = viewers.get(0);
            for (Connection v : viewers) {
                total += v.queuedBytes();
                if (v.queuedBytes() > slowest.queuedBytes()) {
                    slowest = v;
                }
            }
            long after = total + (long) frameBytes * viewers.size();
            if (after <= limits.viewerBudget()) {
                return;
            }
            slowest.close("it is the viewer furthest behind (" + slowest.queuedBytes() + " bytes queued) and the"
                    + " viewers' queues together would hold " + after + " bytes, over the budget of "
                    + limits.viewerBudget() + " (--viewer-budget)");
            viewers.remove(slowest);
        }
    }

    /** A peer on the viewer port sent a message. */
    void received(Connection c, Message m) {
        if (c.isClosed()) {
            return;
        }
        if (!c.greeted() && m instanceof ViewerHello hello) {
            viewerHello(c, hello);
        } else if (!c.greeted() && m instanceof ControlHello hello) {
            controlHello(c, hello);
        } else if (c.isControl() && m instanceof CommsUpdate u) {
            commsUpdate(c, u);
        } else if (c.isControl() && m instanceof ControlRequest r) {
            control.received(c, r);
        } else if (c.greeted() && !c.isControl() && (m instanceof CommsUpdate || m instanceof ControlRequest)) {
            c.sendAndClose(new Bye(Bye.REFUSED + "a viewer cannot change the run; a control client that presents the"
                    + " run secret can (robosim comms, robosim control)"));
            limited.warning("viewers that tried to change the run", () -> "closing " + c.peer() + ": it sent "
                    + typeOf(m) + "; a viewer cannot change the run");
        } else if (c.isControl()) {
            c.close("sent " + typeOf(m) + "; a control client sends controlHello once, then only commsUpdate and"
                    + " controlRequest");
        } else if (!c.greeted()) {
            c.close("sent " + typeOf(m) + "; the viewer port's first message is viewerHello or controlHello");
        } else {
            c.close("sent " + typeOf(m) + "; a viewer sends viewerHello once and then nothing");
        }
    }

    private void viewerHello(Connection c, ViewerHello hello) {
        String name = hello.name() != null ? hello.name() : "(unnamed)";
        String refusal = access.publicView() ? null
                : access.refusal("viewer " + LogLimiter.excerpt(name), hello.token());
        if (refusal == null) {
            viewers.removeIf(Connection::isClosed);
            if (viewers.size() >= limits.maxViewers()) {
                refusal = viewers.size() + " viewers are attached, the most this Environment allows (--max-viewers)";
            }
        }
        if (refusal != null) {
            c.refuse(refusal);
            return;
        }
        // a hello without a name still counts: the next one is a second hello
        c.setName(name);
        viewers.add(c);
        c.send(sim().description());
        // the viewer has seen no drawing yet: it gets them all, not only the last step's changes
        c.send(sim().snapshot().withDrawings(sim().drawings()));
        // anyone may attach when anyone may watch, as often as they like
        limited.info("viewers attached", () -> c.peer() + " attached at step " + sim().stepCount());
    }

    private void controlHello(Connection c, ControlHello hello) {
        String name = hello.name() != null ? hello.name() : "(unnamed)";
        String refusal = access.refusal("control client " + LogLimiter.excerpt(name), hello.token());
        if (refusal == null) {
            controls.removeIf(Connection::isClosed);
            if (controls.size() >= limits.maxControls()) {
                refusal = controls.size() + " control clients are attached, the most this Environment allows"
                        + " (--max-controls)";
            }
        }
        if (refusal != null) {
            c.refuse(refusal);
            return;
        }
        c.setName(name);
        c.becomeControl();
        controls.add(c);
        LOG.info(() -> c.peer() + " attached at step " + sim().stepCount());
    }

    private void commsUpdate(Connection c, CommsUpdate u) {
        CommsSettings now = sim().commsSettings();
        try {
            CommsSettings next = new CommsSettings(
                    u.maxRange() != null ? u.maxRange() : now.maxRange(),
                    u.wallsBlock() != null ? u.wallsBlock() : now.wallsBlock(),
                    u.latencySteps() != null ? u.latencySteps() : now.latencySteps(),
                    u.lossProbability() != null ? u.lossProbability() : now.lossProbability(),
                    u.maxMessageBytes() != null ? u.maxMessageBytes() : now.maxMessageBytes());
            sim().setCommsSettings(next);
            limited.info("changes of the comms settings", () -> c.peer() + " changed the comms settings at step "
                    + sim().stepCount() + " to " + next.describe());
            c.send(new CommsUpdate(next.maxRange(), next.wallsBlock(), next.latencySteps(), next.lossProbability(),
                    next.maxMessageBytes()));
        } catch (IllegalArgumentException e) {
            limited.warning("refused comms settings", () -> "closing " + c.peer()
                    + ": it sent comms settings that break a rule: " + e.getMessage());
            c.sendAndClose(new Bye(Bye.REFUSED + "the comms settings break a rule: " + e.getMessage()));
        }
    }

    /** A viewer's or control client's connection ended. */
    void closed(Connection c) {
        viewers.remove(c);
        controls.remove(c);
    }

    private static String typeOf(Message m) {
        return m.getClass().getSimpleName();
    }
}
