"""Commands of this group are added here."""
