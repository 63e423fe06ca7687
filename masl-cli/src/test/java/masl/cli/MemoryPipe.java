package masl.cli;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * A pipe in memory between two threads of a test, written from any thread and read from any other.
 * Unlike {@link java.io.PipedInputStream}, which reports a broken pipe once the last thread that
 * wrote to it has ended and nothing came for a second or two, it ends only when {@link #close()} is
 * called. An interrupted reader gets an {@link InterruptedIOException}, as from a piped stream (an
 * operating-system pipe's channel would be closed by it).
 */
final class MemoryPipe {

    private final ReentrantLock lock = new ReentrantLock();
    private final Condition written = lock.newCondition();
    private final ByteArrayOutputStream pending = new ByteArrayOutputStream();
    private byte[] readable = new byte[0];
    private int readAt;
    private boolean closed;

    final InputStream in = new InputStream() {
        @Override
        public int read() throws IOException {
            byte[] one = new byte[1];
            return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            if (length == 0) {
                return 0;
            }
            lock.lock();
            try {
                while (readAt == readable.length && pending.size() == 0 && !closed) {
                    try {
                        written.await();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        throw new InterruptedIOException("interrupted while reading the pipe");
                    }
                }
                if (readAt == readable.length) {
                    if (pending.size() == 0) {
                        return -1;
                    }
                    readable = pending.toByteArray();
                    readAt = 0;
                    pending.reset();
                }
                int count = Math.min(length, readable.length - readAt);
                System.arraycopy(readable, readAt, buffer, offset, count);
                readAt += count;
                return count;
            } finally {
                lock.unlock();
            }
        }
    };

    final OutputStream out = new OutputStream() {
        @Override
        public void write(int b) {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] buffer, int offset, int length) {
            lock.lock();
            try {
                pending.write(buffer, offset, length);
                written.signalAll();
            } finally {
                lock.unlock();
            }
        }

        @Override
        public void close() {
            MemoryPipe.this.close();
        }
    };

    /** The reader gets what was written, then the end of the stream. */
    void close() {
        lock.lock();
        try {
            closed = true;
            written.signalAll();
        } finally {
            lock.unlock();
        }
    }
}
