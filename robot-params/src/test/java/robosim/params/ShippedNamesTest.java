package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Optional;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Bare names such as {@code p3dx} stand for the shipped parameter files; paths never do. */
class ShippedNamesTest {
    @ParameterizedTest(name = "{0} is {1}")
    @CsvSource({"p3dx, p3dx.p", "p3dx.p, p3dx.p", "p3dx.xml, p3dx.xml", "scout, scout.p", "p3dx-original.xml, p3dx-original.xml"})
    void aBareNameFindsTheShippedFile(String name, String file) {
        assertEquals(Optional.of(ShippedRobots.dir().resolve(file)), atRoot(() -> RobotParameterFiles.shipped(name)));
    }

    @ParameterizedTest
    @ValueSource(strings = {"p9dx", "", ".", "..", "../robots/p3dx.p", "robots/p3dx", "..\\robots\\p3dx.p", "p3dx-original"})
    void aPathOrAnUnknownNameFindsNothing(String name) {
        assertEquals(Optional.empty(), atRoot(() -> RobotParameterFiles.shipped(name)));
    }

    @Test
    void theNamesListEachFileOnceInTheFormTheyAreFoundBy() {
        var names = atRoot(RobotParameterFiles::shippedNames);
        assertTrue(names.containsAll(java.util.List.of("amigo", "p3at", "p3dx", "p3dx.xml", "p3dx-gripper", "scout",
                "scout.xml", "p3dx-original.xml")), names::toString);
        assertEquals(names.stream().sorted().toList(), names);
        for (String n : names) {
            assertTrue(atRoot(() -> RobotParameterFiles.shipped(n)).isPresent(), n);
        }
    }

    /** Run from a folder of its own, without robosim.root, a program finds the clone its classes came from. */
    @Test
    void withoutTheRootPropertyTheRootIsTheCloneTheClassesCameFrom() {
        String old = System.clearProperty("robosim.root");
        try {
            Path root = RobotParameterFiles.root().toAbsolutePath().normalize();
            // surefire runs in robot-params/, which holds no testLoadFiles: the root is found from the classes
            assertEquals(ShippedRobots.projectRoot().toAbsolutePath().normalize(), root);
            assertEquals(Optional.of(ShippedRobots.dir().resolve("p3dx.p")),
                    RobotParameterFiles.shipped("p3dx").map(p -> p.toAbsolutePath().normalize()));
        } finally {
            if (old != null) {
                System.setProperty("robosim.root", old);
            }
        }
    }

    private static <T> T atRoot(Supplier<T> call) {
        String old = System.setProperty("robosim.root", ShippedRobots.projectRoot().toString());
        try {
            return call.get();
        } finally {
            if (old == null) {
                System.clearProperty("robosim.root");
            } else {
                System.setProperty("robosim.root", old);
            }
        }
    }
}
