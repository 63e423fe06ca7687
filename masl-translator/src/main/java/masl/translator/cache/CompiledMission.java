package masl.translator.cache;

import java.util.Map;

/**
 * What {@code masl run} needs of an accepted program to run it without translating it again: the
 * class files javac made of its generated Java, by binary name, which of them is the mission class,
 * and the diagnostics (warnings) its translation printed, replayed as they were.
 */
public record CompiledMission(String missionClassName, Map<String, byte[]> classFiles, String diagnostics) {

    public CompiledMission {
        classFiles = Map.copyOf(classFiles);
    }
}
