package masl.jade.trust;

import java.util.Arrays;

/**
 * Which sequence numbers of one sender's signed messages a receiver has taken: a message is taken
 * once. A sniffing agent of the platform may resend a control message it saw, signature and all;
 * its sequence number ({@value MissionSecret#SEQUENCE}, which the signature covers) gives it away.
 * Messages may arrive somewhat out of order (several threads send them), so the last {@value #SIZE}
 * numbers below the highest are remembered one by one, as IPsec's anti-replay window does; older
 * ones are refused. Not thread-safe: one receiving agent's thread.
 */
final class ReplayWindow {

    static final int SIZE = 1024;

    private final long[] seen = new long[SIZE / Long.SIZE];
    private long highest;

    /** Whether the message numbered {@code sequence} (its text) is new, which takes it; false for a replay or no number. */
    boolean take(String sequence) {
        long number;
        try {
            number = sequence == null ? 0 : Long.parseLong(sequence);
        } catch (NumberFormatException notANumber) {
            return false;
        }
        if (number <= 0 || number <= highest - SIZE) {
            return false;
        }
        if (number > highest) {
            forget(number - highest);
            highest = number;
        }
        int bit = (int) (number % SIZE);
        long mask = 1L << (bit % Long.SIZE);
        if ((seen[bit / Long.SIZE] & mask) != 0) {
            return false;
        }
        seen[bit / Long.SIZE] |= mask;
        return true;
    }

    /** Clears the bits of the numbers that leave the window as the highest moves up by {@code shift}. */
    private void forget(long shift) {
        if (shift >= SIZE) {
            Arrays.fill(seen, 0);
            return;
        }
        for (long n = highest + 1; n <= highest + shift; n++) {
            int bit = (int) (n % SIZE);
            seen[bit / Long.SIZE] &= ~(1L << (bit % Long.SIZE));
        }
    }
}
