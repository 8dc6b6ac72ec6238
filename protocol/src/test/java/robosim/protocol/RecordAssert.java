package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.RecordComponent;
import java.util.List;

/**
 * Compares records component by component, arrays by content: the messages hold {@code int[]} and
 * {@code double[]}, which a record's own {@code equals} compares by identity.
 */
final class RecordAssert {
    private RecordAssert() {
    }

    static void assertDeepEquals(Object expected, Object actual) {
        assertDeepEquals(expected, actual, expected == null ? "value" : expected.getClass().getSimpleName());
    }

    private static void assertDeepEquals(Object expected, Object actual, String path) {
        if (expected == null || actual == null) {
            assertEquals(expected, actual, path);
        } else if (expected instanceof List<?> e) {
            List<?> a = assertInstanceOf(List.class, actual, path);
            assertEquals(e.size(), a.size(), path + ".size()");
            for (int i = 0; i < e.size(); i++) {
                assertDeepEquals(e.get(i), a.get(i), path + "[" + i + "]");
            }
        } else if (expected instanceof int[] e) {
            assertArrayEquals(e, assertInstanceOf(int[].class, actual, path), path);
        } else if (expected instanceof StateParts e) {
            StateParts a = assertInstanceOf(StateParts.class, actual, path);
            for (StatePart<?> part : StateParts.ALL) {
                assertDeepEquals(e.get(part), a.get(part), path + "." + part.name());
            }
        } else if (expected instanceof double[] e) {
            assertArrayEquals(e, assertInstanceOf(double[].class, actual, path), path);
        } else if (expected.getClass().isRecord()) {
            assertEquals(expected.getClass(), actual.getClass(), path);
            for (RecordComponent c : expected.getClass().getRecordComponents()) {
                assertDeepEquals(component(c, expected), component(c, actual), path + "." + c.getName());
            }
        } else {
            assertEquals(expected, actual, path);
        }
    }

    private static Object component(RecordComponent c, Object record) {
        try {
            return c.getAccessor().invoke(record);
        } catch (IllegalAccessException | InvocationTargetException e) {
            throw new AssertionError("cannot read " + c.getName() + " of " + record.getClass(), e);
        }
    }
}
