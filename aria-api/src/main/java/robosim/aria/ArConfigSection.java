package robosim.aria;

import java.util.ArrayList;
import java.util.List;

/**
 * ARIA's {@code ArConfigSection}: a named group of an {@link ArConfig}'s parameters, with a comment
 * and flags; a file gives it as {@code Section NAME}. Names are matched in any case, as ARIA's.
 * Follows {@code ArConfigSection} in ARIA's {@code ArConfig.h} and {@code ArConfig.cpp}.
 */
public final class ArConfigSection {
    private String name;
    private String comment;
    private String categoryName = "";
    private final List<String> flags = new ArrayList<>();
    private final List<ArConfigArg> params = new ArrayList<>();

    /**
     * @param name    its name ("" for the parameters of no section)
     * @param comment its comment, or null
     */
    public ArConfigSection(String name, String comment) {
        this.name = name == null ? "" : name;
        this.comment = comment == null ? "" : comment;
    }

    /** @return its name */
    public String getName() {
        return name;
    }

    /** @param name its name from now on */
    public void setName(String name) {
        this.name = name == null ? "" : name;
    }

    /** @return its comment ("" if none) */
    public String getComment() {
        return comment;
    }

    /** @param comment its comment from now on */
    public void setComment(String comment) {
        this.comment = comment == null ? "" : comment;
    }

    /** @return the category {@link ArConfig#addSection} put it in ("" if none) */
    public String getCategoryName() {
        return categoryName;
    }

    void setCategoryName(String categoryName) {
        this.categoryName = categoryName == null ? "" : categoryName;
    }

    /** @return its flags, separated by '|' as ARIA writes them ("" if none) */
    public String getFlags() {
        return String.join("|", flags);
    }

    /** @param flag a flag @return whether the section has it (exactly, as ARIA compares) */
    public boolean hasFlag(String flag) {
        return flags.stream().anyMatch(f -> f.equals(flag));
    }

    /**
     * ARIA's {@code addFlags}: adds each word of {@code flags} it does not have yet.
     *
     * @param flags one or more flags, separated by white space or '|'
     * @return true
     */
    public boolean addFlags(String flags) {
        for (String f : ConfigText.words(flags == null ? "" : flags.replace('|', ' '))) {
            if (!hasFlag(f)) {
                this.flags.add(f);
            }
        }
        return true;
    }

    /** @param flag a flag to take off @return true */
    public boolean remFlag(String flag) {
        this.flags.removeIf(f -> f.equals(flag));
        return true;
    }

    /**
     * @return its parameters, in the order added: the list itself, as ARIA's {@code getParams}
     *         gives (change it only if you know what to do)
     */
    public List<ArConfigArg> getParams() {
        return params;
    }

    /** @param paramName a name, any case @return the last parameter with it (saved unknowns left out), or null */
    public ArConfigArg findParam(String paramName) {
        return findParam(paramName, false);
    }

    /**
     * ARIA's {@code ArConfigSection::findParam}.
     *
     * @param paramName            a name, any case
     * @param isAllowStringHolders whether saved unknown parameters count
     * @return the last parameter with that name, or null
     */
    public ArConfigArg findParam(String paramName, boolean isAllowStringHolders) {
        ArConfigArg found = null;
        for (ArConfigArg p : params) {
            if (!isAllowStringHolders && p.getType() == ArConfigArg.Type.STRING_HOLDER) {
                continue;
            }
            if (p.getName().equalsIgnoreCase(paramName)) {
                found = p;
            }
        }
        return found;
    }

    /**
     * @param highestPriority the most important priority counted
     * @param lowestPriority  the least important
     * @return whether a parameter (separators left out) has a priority between them
     */
    public boolean containsParamsOfPriority(ArPriority highestPriority, ArPriority lowestPriority) {
        return params.stream().anyMatch(p -> p.getType() != ArConfigArg.Type.SEPARATOR
                && p.getConfigPriority().compareTo(highestPriority) >= 0
                && p.getConfigPriority().compareTo(lowestPriority) <= 0);
    }

    /** @param paramName a name @return whether a saved unknown parameter of that name was taken off */
    public boolean remStringHolder(String paramName) {
        return params.removeIf(p -> p.getType() == ArConfigArg.Type.STRING_HOLDER
                && p.getName().equalsIgnoreCase(paramName));
    }
}
