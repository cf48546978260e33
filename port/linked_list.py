"""LinkedList and LinkedListNode: .NET's System.Collections.Generic.LinkedList<T>, as ACE's motion layer uses it.

ACE keeps its animation queue (Sequence.AnimList, CurrAnim, FirstCyclic), a MotionState's
Modifiers and Actions, and the managers' pending lists in .NET LinkedLists and holds on to their
nodes. What the port must keep of .NET's behaviour:
- a node's `next` is None at the last node and its `previous` None at the first (LinkedListNode.Next
  and .Previous), and `list` is the list holding it;
- removing a node (or clearing the list) detaches it: its `list`, `next` and `previous` become None,
  so code holding a removed node sees what ACE sees;
- `Remove(T value)` removes the first node whose value equals the given one under
  EqualityComparer<T>.Default, which for ACE's classes here (AnimSequenceNode, Motion, MotionNode,
  AnimNode: none overrides Equals) is reference equality;
- `Remove(node)` of a node of another list (or none) and `RemoveFirst`/`RemoveLast` of an empty list
  throw InvalidOperationException;
- node equality (`node.Equals(other)`) is reference equality: `equals` here, which a None node
  cannot answer (AttributeError, reported as NullReferenceException, as .NET throws).
"""

from __future__ import annotations

from .anchors import harness
from .errors import InvalidOperationException


class LinkedListNode:
    __slots__ = ("value", "next", "previous", "list")

    def __init__(self, value):
        self.value = value
        self.next: LinkedListNode | None = None
        self.previous: LinkedListNode | None = None
        self.list: LinkedList | None = None

    @harness(".NET LinkedListNode.Equals: reference equality")
    def equals(self, other) -> bool:
        return self is other


class LinkedList:
    __slots__ = ("first", "last", "count")

    def __init__(self):
        self.first: LinkedListNode | None = None
        self.last: LinkedListNode | None = None
        self.count = 0

    def __len__(self) -> int:
        return self.count

    def __iter__(self):
        """The values, first to last (foreach over a LinkedList)."""
        node = self.first
        while node is not None:
            yield node.value
            node = node.next

    @harness(".NET LinkedList.AddLast(T)")
    def add_last(self, value) -> LinkedListNode:
        node = LinkedListNode(value)
        node.list = self
        node.previous = self.last
        if self.last is None:
            self.first = node
        else:
            self.last.next = node
        self.last = node
        self.count += 1
        return node

    @harness(".NET LinkedList.AddFirst(T)")
    def add_first(self, value) -> LinkedListNode:
        node = LinkedListNode(value)
        node.list = self
        node.next = self.first
        if self.first is None:
            self.last = node
        else:
            self.first.previous = node
        self.first = node
        self.count += 1
        return node

    @harness(".NET LinkedList.Find(T): the first node holding the value (reference equality for ACE's classes)")
    def find(self, value) -> LinkedListNode | None:
        node = self.first
        while node is not None:
            if node.value is value:
                return node
            node = node.next
        return None

    @harness(".NET LinkedList.Remove(LinkedListNode<T>): InvalidOperationException for a node not in this list")
    def remove_node(self, node: LinkedListNode) -> None:
        if node is None:
            raise InvalidOperationException("LinkedList.Remove(null node)")  # .NET: ArgumentNullException
        if node.list is not self:
            raise InvalidOperationException("LinkedList.Remove: the node does not belong to this list")
        if node.previous is None:
            self.first = node.next
        else:
            node.previous.next = node.next
        if node.next is None:
            self.last = node.previous
        else:
            node.next.previous = node.previous
        node.next = node.previous = node.list = None
        self.count -= 1

    @harness(".NET LinkedList.Remove(T): removes the first node holding the value; False when none does")
    def remove(self, value) -> bool:
        node = self.find(value)
        if node is None:
            return False
        self.remove_node(node)
        return True

    @harness(".NET LinkedList.RemoveFirst: InvalidOperationException when empty")
    def remove_first(self) -> None:
        if self.first is None:
            raise InvalidOperationException("LinkedList.RemoveFirst: the list is empty")
        self.remove_node(self.first)

    @harness(".NET LinkedList.RemoveLast: InvalidOperationException when empty")
    def remove_last(self) -> None:
        if self.last is None:
            raise InvalidOperationException("LinkedList.RemoveLast: the list is empty")
        self.remove_node(self.last)

    @harness(".NET LinkedList.Clear: every node detached")
    def clear(self) -> None:
        node = self.first
        while node is not None:
            following = node.next
            node.next = node.previous = node.list = None
            node = following
        self.first = self.last = None
        self.count = 0
