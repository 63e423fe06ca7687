package masl.e2e;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/** The samples of a simulated run's {@code trajectories.csv} ({@code time,agent,x,y,z,heading}). */
final class Trajectories {

    /** One sample: a robot's main body (its centre of mass) at a time. */
    record Sample(double time, String agent, double x, double y, double heading) {}

    private final List<Sample> samples;

    private Trajectories(List<Sample> samples) {
        this.samples = samples;
    }

    static Trajectories read(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        List<Sample> samples = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] cells = line.split(",");
            samples.add(new Sample(Double.parseDouble(cells[0]), cells[1], Double.parseDouble(cells[2]),
                    Double.parseDouble(cells[3]), Double.parseDouble(cells[5])));
        }
        return new Trajectories(samples);
    }

    List<Sample> of(String agent) {
        return samples.stream().filter(sample -> sample.agent().equals(agent)).collect(Collectors.toList());
    }

    /** The agent's last sample. */
    Sample last(String agent) {
        List<Sample> own = of(agent);
        return own.get(own.size() - 1);
    }
}
