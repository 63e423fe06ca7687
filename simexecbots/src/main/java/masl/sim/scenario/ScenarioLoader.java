package masl.sim.scenario;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import javax.lang.model.SourceVersion;
import masl.runtime.diagnostic.Diagnostic;
import masl.sim.physics.PhysicsSettings;
import masl.sim.xode.SecureXmlReader;
import masl.sim.xode.XodeElement;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeProblem;
import masl.sim.xode.XodeSource;

/**
 * Reads scenario files. The XML parser never fetches a DTD nor expands an external entity; every
 * problem of a file is reported, each as {@code file:line:column: error: message}.
 *
 * <pre>{@code
 * <scenario name="two robots">
 *   <physics step="0.01" iterations="20" gravity="0 0 -9.81" seed="7" friction="1"
 *            mode="lock-step" slicesPerStep="64" realTimeFactor="0" duration="20"/>
 *   <world file="arena.xode"/>                    <!-- or resource="…" on the class path -->
 *   <agent name="k0" model="wheeled"><pose x="0" y="0" heading="90"/></agent>
 *   <agent name="a0" model="maam-atom" class="my.Atom" body="my-atom.xode"/>
 *   <agent name="planner" class="my.Planner" descriptor="Planner.xml"/>
 *   <fault agent="k0" time="12.5"/>
 *   <initialisation class="my.Setup"/>
 *   <mission file="sweep.masl"/>
 *   <output sample="0.1"/>
 * </scenario>
 * }</pre>
 *
 * Every element but {@code scenario} is optional; {@code physics}, {@code initialisation},
 * {@code mission} and {@code output} appear at most once. Defaults: {@link PhysicsSettings#defaults()},
 * lock-step, 64 slices per step, no duration limit, samples every 0.1 s. Bounds: step 1e-6 to 1 s,
 * iterations 1 to {@value #MAX_ITERATIONS}, contacts 1 to {@value #MAX_CONTACTS}, slicesPerStep 1 to
 * {@value #MAX_SLICES_PER_STEP}, realTimeFactor 0 or 0.001 to 1000. Headings are degrees;
 * {@code mode} is {@code lock-step} or {@code threaded}. File paths are relative to the scenario's
 * folder. Unknown elements and attributes are errors: a scenario is this project's own format.
 */
public final class ScenarioLoader {

    private static final Map<String, Set<String>> ATTRIBUTES = Map.of(
            "scenario", Set.of("name"),
            "physics", Set.of("step", "iterations", "gravity", "seed", "friction", "contacts", "mode", "slicesPerStep",
                    "realTimeFactor", "duration"),
            "world", Set.of("file", "resource"),
            "agent", Set.of("name", "model", "class", "descriptor", "body"),
            "pose", Set.of("x", "y", "heading"),
            "fault", Set.of("agent", "time"),
            "initialisation", Set.of("class"),
            "mission", Set.of("file"),
            "output", Set.of("sample"));
    private static final Set<String> SINGLE = Set.of("physics", "initialisation", "mission", "output");
    /**
     * Bounds of the physics numbers. A physics step cannot be interrupted, so {@code --timeout} is
     * honoured between steps: these bounds keep one step short (a few milliseconds for the robot
     * models at the most iterations), and keep simulated time moving.
     */
    static final int MAX_ITERATIONS = 10_000;
    static final int MAX_CONTACTS = 256;
    static final int MAX_SLICES_PER_STEP = 1_000_000;
    static final double MIN_STEP = 1e-6;
    static final double MAX_STEP = 1;
    static final double MAX_REAL_TIME_FACTOR = 1000;

    /** Reads the scenario file at {@code file}. */
    public Scenario load(Path file) throws ScenarioException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new ScenarioException(List.of(Diagnostic.error(file.toString(), 1, 1, "cannot read the scenario: " + e.getMessage())));
        }
        Path folder = file.toAbsolutePath().getParent();
        return load(file.toString(), text, folder);
    }

    /**
     * Reads a scenario from text.
     *
     * @param name   the file name messages use
     * @param folder where relative paths are resolved
     */
    public Scenario load(String name, String text, Path folder) throws ScenarioException {
        XodeElement root;
        try {
            root = new SecureXmlReader(name, text).read();
        } catch (XodeException e) {
            throw new ScenarioException(e.problems().stream().map(XodeProblem::diagnostic).toList());
        }
        return new Reading(name, folder).read(root);
    }

    /** The state of reading one file: its problems so far. */
    private static final class Reading {
        private final String fileName;
        private final Path folder;
        private final List<Diagnostic> errors = new ArrayList<>();

        Reading(String fileName, Path folder) {
            this.fileName = fileName;
            this.folder = folder;
        }

        Scenario read(XodeElement root) throws ScenarioException {
            if (!root.name().equals("scenario")) {
                error(root, "the root element must be <scenario>, not <" + root.name() + ">");
                throw new ScenarioException(errors);
            }
            checkAttributes(root);
            PhysicsSettings physics = PhysicsSettings.defaults().withRealTimeFactor(0);
            Scenario.Mode mode = Scenario.Mode.LOCK_STEP;
            int slicesPerStep = 64;
            double duration = 0;
            double sample = 0.1;
            Optional<Scenario.Initialisation> initialisation = Optional.empty();
            Optional<Path> mission = Optional.empty();
            List<XodeSource> worlds = new ArrayList<>();
            List<Scenario.Agent> agents = new ArrayList<>();
            List<XodeElement> faultElements = new ArrayList<>();
            Set<String> seen = new HashSet<>();
            for (XodeElement child : root.children()) {
                if (!ATTRIBUTES.containsKey(child.name()) || child.name().equals("scenario") || child.name().equals("pose")) {
                    error(child, "unknown element <" + child.name() + "> in <scenario>");
                    continue;
                }
                checkAttributes(child);
                if (SINGLE.contains(child.name()) && !seen.add(child.name())) {
                    error(child, "<" + child.name() + "> given twice");
                    continue;
                }
                switch (child.name()) {
                    case "physics" -> {
                        physics = physics(child, physics);
                        mode = mode(child);
                        slicesPerStep = whole(child, "slicesPerStep", 64, MAX_SLICES_PER_STEP);
                        duration = number(child, "duration", 0, 0, false);
                    }
                    case "world" -> world(child).ifPresent(worlds::add);
                    case "agent" -> agent(child, agents).ifPresent(agents::add);
                    case "fault" -> faultElements.add(child);
                    case "initialisation" -> initialisation = className(child, "class")
                            .map(c -> new Scenario.Initialisation(c, child.location()));
                    case "mission" -> mission = required(child, "file").map(this::resolve);
                    case "output" -> sample = number(child, "sample", 0.1, 0, true);
                    default -> throw new IllegalStateException(child.name());
                }
            }
            List<Scenario.Fault> faults = new ArrayList<>();
            for (XodeElement element : faultElements) {
                fault(element, agents).ifPresent(faults::add);
            }
            if (!errors.isEmpty()) {
                throw new ScenarioException(errors.stream().sorted().toList());
            }
            String name = root.attribute("name").orElse(Path.of(fileName).getFileName().toString());
            return new Scenario(name, fileName, physics, mode, slicesPerStep, duration, worlds, agents, faults,
                    initialisation, mission, sample);
        }

        private PhysicsSettings physics(XodeElement element, PhysicsSettings defaults) {
            double step = number(element, "step", defaults.stepSize(), 0, true);
            if (step < MIN_STEP || step > MAX_STEP) {
                error(element, "step: " + element.attribute("step").orElse("") + " must be from 0.000001 to "
                        + formatBound(MAX_STEP) + " (seconds)");
                step = defaults.stepSize();
            }
            int iterations = whole(element, "iterations", defaults.solverIterations(), MAX_ITERATIONS);
            double friction = number(element, "friction", defaults.friction(), 0, false);
            int contacts = whole(element, "contacts", defaults.maxContacts(), MAX_CONTACTS);
            double realTime = number(element, "realTimeFactor", defaults.realTimeFactor(), 0, false);
            if (realTime > MAX_REAL_TIME_FACTOR || realTime > 0 && realTime < 1 / MAX_REAL_TIME_FACTOR) {
                error(element, "realTimeFactor: " + element.attribute("realTimeFactor").orElse("") + " must be 0 (as fast"
                        + " as possible) or from " + 1 / MAX_REAL_TIME_FACTOR + " to " + formatBound(MAX_REAL_TIME_FACTOR));
                realTime = defaults.realTimeFactor();
            }
            long seed = defaults.seed();
            Optional<String> seedText = element.attribute("seed");
            if (seedText.isPresent()) {
                try {
                    seed = Long.parseLong(seedText.get().trim());
                } catch (NumberFormatException e) {
                    error(element, "seed: '" + seedText.get() + "' is not a whole number");
                }
            }
            double[] gravity = {defaults.gravityX(), defaults.gravityY(), defaults.gravityZ()};
            Optional<String> gravityText = element.attribute("gravity");
            if (gravityText.isPresent()) {
                String[] parts = gravityText.get().trim().split("\\s+");
                if (parts.length != 3) {
                    error(element, "gravity: three numbers expected (x y z), got '" + gravityText.get() + "'");
                } else {
                    for (int i = 0; i < 3; i++) {
                        gravity[i] = parse(element, "gravity", parts[i]);
                    }
                }
            }
            return new PhysicsSettings(step, iterations, gravity[0], gravity[1], gravity[2], seed, friction, contacts, realTime);
        }

        private Scenario.Mode mode(XodeElement element) {
            String mode = element.attribute("mode").orElse("lock-step");
            switch (mode) {
                case "lock-step":
                    return Scenario.Mode.LOCK_STEP;
                case "threaded":
                    return Scenario.Mode.THREADED;
                default:
                    error(element, "mode: '" + mode + "' is neither 'lock-step' nor 'threaded'");
                    return Scenario.Mode.LOCK_STEP;
            }
        }

        private Optional<XodeSource> world(XodeElement element) {
            Optional<String> file = element.attribute("file");
            Optional<String> resource = element.attribute("resource");
            if (file.isPresent() == resource.isPresent()) {
                error(element, "<world> needs exactly one of 'file' and 'resource'");
                return Optional.empty();
            }
            return file.isPresent() ? existingFile(element, file.get()).map(XodeSource::file)
                    : Optional.of(XodeSource.resource(resource.get()));
        }

        private Optional<Scenario.Agent> agent(XodeElement element, List<Scenario.Agent> earlier) {
            Optional<String> name = required(element, "name");
            if (name.isPresent() && !SourceVersion.isName(name.get())) {
                error(element, "name: '" + name.get() + "' is not a MASL identifier");
            }
            if (name.isPresent() && earlier.stream().anyMatch(a -> a.name().equals(name.get()))) {
                error(element, "agent '" + name.get() + "' placed twice");
            }
            Optional<RobotModel> model = Optional.empty();
            Optional<String> modelName = element.attribute("model");
            if (modelName.isPresent()) {
                model = RobotModel.named(modelName.get());
                if (model.isEmpty()) {
                    error(element, "model: unknown robot model '" + modelName.get() + "' (known: wheeled, maam-atom)");
                }
            }
            Optional<String> implementation = element.attribute("class").isPresent() ? className(element, "class") : Optional.empty();
            Optional<Path> descriptor = element.attribute("descriptor").flatMap(d -> existingFile(element, d));
            Optional<XodeSource> body = Optional.empty();
            if (element.attribute("body").isPresent()) {
                if (modelName.isEmpty()) {
                    error(element, "body: only a robot agent (with a model) has a body");
                }
                body = existingFile(element, element.attribute("body").get()).map(XodeSource::file);
            }
            double x = 0;
            double y = 0;
            double heading = 0;
            for (XodeElement child : element.children()) {
                if (!child.name().equals("pose")) {
                    error(child, "unknown element <" + child.name() + "> in <agent>");
                } else if (modelName.isEmpty()) {
                    error(child, "<pose>: only a robot agent (with a model) has a pose");
                } else {
                    checkAttributes(child);
                    x = number(child, "x", 0, Double.NEGATIVE_INFINITY, false);
                    y = number(child, "y", 0, Double.NEGATIVE_INFINITY, false);
                    heading = Math.toRadians(number(child, "heading", 0, Double.NEGATIVE_INFINITY, false));
                }
            }
            if (name.isEmpty()) {
                return Optional.empty();
            }
            return Optional.of(new Scenario.Agent(name.get(), model, implementation, descriptor, body, x, y, heading,
                    element.location()));
        }

        private Optional<Scenario.Fault> fault(XodeElement element, List<Scenario.Agent> agents) {
            Optional<String> agent = required(element, "agent");
            double time = number(element, "time", 0, 0, false);
            if (agent.isEmpty()) {
                return Optional.empty();
            }
            Optional<Scenario.Agent> placed = agents.stream().filter(a -> a.name().equals(agent.get())).findFirst();
            if (placed.isEmpty()) {
                error(element, "agent: no agent '" + agent.get() + "' in this scenario");
                return Optional.empty();
            }
            if (placed.get().model().orElse(null) != RobotModel.WHEELED) {
                error(element, "agent: '" + agent.get() + "' is not a wheeled robot; only they can fail");
                return Optional.empty();
            }
            return Optional.of(new Scenario.Fault(agent.get(), time, element.location()));
        }

        private Optional<String> className(XodeElement element, String attribute) {
            Optional<String> name = required(element, attribute);
            if (name.isPresent() && !SourceVersion.isName(name.get())) {
                error(element, attribute + ": '" + name.get() + "' is not a Java class name");
                return Optional.empty();
            }
            return name;
        }

        private Optional<Path> existingFile(XodeElement element, String relative) {
            Path path = resolve(relative);
            if (!Files.isRegularFile(path)) {
                error(element, "file '" + relative + "' not found (looked for " + path + ")");
                return Optional.empty();
            }
            return Optional.of(path);
        }

        private Path resolve(String relative) {
            return folder == null ? Path.of(relative) : folder.resolve(relative).normalize();
        }

        private Optional<String> required(XodeElement element, String attribute) {
            Optional<String> value = element.attribute(attribute);
            if (value.isEmpty() || value.get().isBlank()) {
                error(element, "<" + element.name() + "> needs the attribute '" + attribute + "'");
                return Optional.empty();
            }
            return value.map(String::trim);
        }

        /** The attribute as a number ≥ {@code min} (&gt; min when {@code exclusive}), else {@code fallback}. */
        private double number(XodeElement element, String attribute, double fallback, double min, boolean exclusive) {
            Optional<String> text = element.attribute(attribute);
            if (text.isEmpty()) {
                return fallback;
            }
            double value = parse(element, attribute, text.get());
            if (Double.isNaN(value)) {
                return fallback;
            }
            if (exclusive ? !(value > min) : !(value >= min)) {
                error(element, attribute + ": " + text.get() + " must be " + (exclusive ? "greater than " : "at least ") + formatBound(min));
                return fallback;
            }
            return value;
        }

        /** The attribute as a whole number from 1 to {@code max}, else {@code fallback}. */
        private int whole(XodeElement element, String attribute, int fallback, int max) {
            Optional<String> text = element.attribute(attribute);
            if (text.isEmpty()) {
                return fallback;
            }
            String digits = text.get().trim();
            if (digits.matches("[0-9]{1,9}")) {
                int value = Integer.parseInt(digits);
                if (value >= 1 && value <= max) {
                    return value;
                }
            }
            error(element, attribute + ": '" + text.get() + "' is not a whole number from 1 to " + max);
            return fallback;
        }

        private double parse(XodeElement element, String attribute, String text) {
            try {
                double value = Double.parseDouble(text.trim());
                if (Double.isFinite(value)) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // reported below
            }
            error(element, attribute + ": '" + text + "' is not a finite number");
            return Double.NaN;
        }

        private void checkAttributes(XodeElement element) {
            Set<String> known = ATTRIBUTES.get(element.name());
            for (String attribute : element.attributes().keySet()) {
                if (!known.contains(attribute)) {
                    error(element, "unknown attribute '" + attribute + "' on <" + element.name() + ">");
                }
            }
        }

        private void error(XodeElement element, String message) {
            errors.add(element.location().error(message));
        }

        private static String formatBound(double bound) {
            return bound == Math.rint(bound) ? Long.toString((long) bound) : Double.toString(bound);
        }
    }
}
