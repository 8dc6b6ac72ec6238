package robosim.aria;

/** The checks of the standard actions' parameters: each names the parameter, the value and the rule. */
final class ActionArgs {
    private ActionArgs() {
    }

    /** @return the value, if it is a finite number of at least 0 */
    static double nonNegative(String action, String parameter, double value) {
        if (!Double.isFinite(value) || value < 0) {
            throw new IllegalArgumentException(value + " was supplied for " + parameter + " of " + action
                    + ": " + parameter + " must be a number of at least 0");
        }
        return value;
    }

    /** @return the value, if it is a finite number above 0 */
    static double positive(String action, String parameter, double value) {
        if (!Double.isFinite(value) || value <= 0) {
            throw new IllegalArgumentException(value + " was supplied for " + parameter + " of " + action
                    + ": " + parameter + " must be a number greater than 0");
        }
        return value;
    }

    /** @return the value, if it is a finite number */
    static double finite(String action, String parameter, double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(value + " was supplied for " + parameter + " of " + action
                    + ": " + parameter + " must be a finite number");
        }
        return value;
    }

    /** @return the pose, if it is not null */
    static ArPose pose(String action, String parameter, ArPose pose) {
        if (pose == null) {
            throw new IllegalArgumentException("no pose was supplied for " + parameter + " of " + action
                    + ": " + parameter + " must be a pose");
        }
        return new ArPose(finite(action, parameter + " x", pose.getX()), finite(action, parameter + " y", pose.getY()),
                finite(action, parameter + " th", pose.getTh()));
    }
}
