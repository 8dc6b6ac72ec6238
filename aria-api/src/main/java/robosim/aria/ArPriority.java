package robosim.aria;

/**
 * ARIA's {@code ArPriority::Priority}: how important a configuration parameter is to a user, from
 * {@link #IMPORTANT} (everyone sets it) to {@link #CALIBRATION} (one robot's hardware). A port
 * writes C++'s {@code ArPriority::NORMAL} as {@code ArPriority.NORMAL}; ARIA's other names for the
 * same levels ({@link #BASIC}, {@link #TRIVIAL}, ...) are constants of the same values. Follows
 * {@code ArPriority} in ARIA's {@code ariaUtil.h} and {@code ariaUtil.cpp}.
 */
public enum ArPriority {
    /** Basic things that should be modified to suit (ARIA's name for it: "Basic"). */
    IMPORTANT("Basic"),
    /** Intermediate things that users may want to modify ("Intermediate"). */
    NORMAL("Intermediate"),
    /** Advanced items that probably should not be modified ("Advanced"). */
    DETAILED("Advanced"),
    /** Items that only expert users or developers should modify ("Expert"). */
    EXPERT("Expert"),
    /** Items set at the factory, often for a robot model ("Factory"). */
    FACTORY("Factory"),
    /** Items that apply to one particular piece of hardware ("Calibration"). */
    CALIBRATION("Calibration");

    /** {@link #IMPORTANT}, by its other name. */
    public static final ArPriority BASIC = IMPORTANT;
    /** The first priority, {@link #IMPORTANT}. */
    public static final ArPriority FIRST_PRIORITY = IMPORTANT;
    /** {@link #NORMAL}, by its other name. */
    public static final ArPriority INTERMEDIATE = NORMAL;
    /** {@link #DETAILED}, by its historic name. */
    public static final ArPriority TRIVIAL = DETAILED;
    /** {@link #DETAILED}, by its other name. */
    public static final ArPriority ADVANCED = DETAILED;
    /** The last priority, {@link #CALIBRATION}. */
    public static final ArPriority LAST_PRIORITY = CALIBRATION;
    /** How many priorities there are (ARIA's {@code PRIORITY_COUNT}). */
    public static final int PRIORITY_COUNT = 6;

    private final String displayName;

    ArPriority(String displayName) {
        this.displayName = displayName;
    }

    /**
     * @param priority a priority
     * @return its displayable name ("Basic", "Intermediate", "Advanced", "Expert", "Factory",
     *         "Calibration"), or "Unknown" for null: ARIA's {@code ArPriority::getPriorityName}
     */
    public static String getPriorityName(ArPriority priority) {
        return priority == null ? "Unknown" : priority.displayName;
    }

    /**
     * ARIA's {@code ArPriority::getPriorityFromName}: the priority of a displayable name, any case.
     *
     * @param text a name as {@link #getPriorityName} gives it
     * @param ok   if not null, {@code ok[0]} is set to whether the name was known
     * @return its priority, or {@link #LAST_PRIORITY} (logged) if the name is empty or unknown
     */
    public static ArPriority getPriorityFromName(String text, boolean[] ok) {
        if (ok != null) {
            ok[0] = false;
        }
        if (text == null || text.isEmpty()) {
            ArLog.log(ArLog.Normal, "ArPriority::getPriorityFromName() error finding priority for empty text");
            return LAST_PRIORITY;
        }
        for (ArPriority p : values()) {
            if (p.displayName.equalsIgnoreCase(text)) {
                if (ok != null) {
                    ok[0] = true;
                }
                return p;
            }
        }
        ArLog.log(ArLog.Normal, "ArPriority::getPriorityFromName() error finding priority for %s", text);
        return LAST_PRIORITY;
    }

    /** @param text a priority's displayable name @return its priority, as {@link #getPriorityFromName(String, boolean[])} */
    public static ArPriority getPriorityFromName(String text) {
        return getPriorityFromName(text, null);
    }
}
