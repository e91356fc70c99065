package org.emini.harness.load;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/**
 * What went wrong with a file, in words. The JDK's file-system exceptions carry only the path as their
 * message ({@code NoSuchFileException: nope.phy}), which printed alone says nothing.
 */
public final class IoText {
    private IoText() {
    }

    /** The problem, with the file named when the exception names one ("nope.phy: no such file"). */
    public static String describe(IOException e) {
        String what;
        if (e instanceof NoSuchFileException) {
            what = "no such file or folder";
        } else if (e instanceof AccessDeniedException) {
            what = "permission denied";
        } else if (e instanceof FileAlreadyExistsException) {
            what = "a file is in the way (a folder was needed, or the file exists)";
        } else if (e instanceof NotDirectoryException) {
            what = "not a folder";
        } else if (e instanceof DirectoryNotEmptyException) {
            what = "the folder is not empty";
        } else if (e instanceof FileSystemException fs) {
            what = fs.getReason() != null ? fs.getReason() : e.getClass().getSimpleName();
        } else {
            what = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
        }
        if (e instanceof FileSystemException fs && fs.getFile() != null) {
            return fs.getFile() + (fs.getOtherFile() != null ? " -> " + fs.getOtherFile() : "") + ": " + what;
        }
        return what;
    }
}
