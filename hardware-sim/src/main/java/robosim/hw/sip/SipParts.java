package robosim.hw.sip;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import robosim.pioneer.Sip;
import robosim.protocol.RobotState;
import robosim.protocol.StateParts;

/**
 * The parts a SIP carries, and one connection's instance of each: the one place a part is taught
 * to travel in a SIP. (The laser's scans and the true pose travel in packets of their own.)
 */
public final class SipParts {
    /** Every part a SIP carries, made for a connection. */
    public static final List<Function<SipContext, SipPart>> ALL = List.of(
            SonarInSip::new,
            BumpersInSip::new,
            BatteryInSip::new,
            GripperInSip::new);

    private final List<SipPart> parts = new ArrayList<>();

    /**
     * @param context what the connection's parts are made from
     */
    public SipParts(SipContext context) {
        for (Function<SipContext, SipPart> kind : ALL) {
            parts.add(kind.apply(context));
        }
    }

    /**
     * @param state the robot's state
     * @param sip   the SIP's fields, the writer's own already set
     */
    public void write(RobotState state, SipFields sip) {
        for (SipPart p : parts) {
            p.write(state, sip);
        }
    }

    /**
     * @param sip   a SIP received
     * @param parts the state's parts so far
     * @return the parts with every SIP part's
     */
    public StateParts read(Sip sip, StateParts parts) {
        StateParts out = parts;
        for (SipPart p : this.parts) {
            out = p.read(sip, out);
        }
        return out;
    }
}
